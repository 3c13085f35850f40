list(APPEND TOONFACE_CORE_SOURCES
  face/pointtable.h face/pointtable.cpp
  face/facemodel.h face/facemodel.cpp
  face/fapu.h face/fapu.cpp
  face/mouthshape.h face/mouthshape.cpp
  face/emotion.h face/emotion.cpp
  face/pose.h face/pose.cpp
  face/averageface.h face/averageface.cpp)
