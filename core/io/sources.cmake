list(APPEND TOONFACE_CORE_SOURCES
  io/jsonfield.h io/jsonfield.cpp
  io/pointsjson.h io/pointsjson.cpp
  io/facejson.h io/facejson.cpp
  io/project.h io/project.cpp
  io/imageio.h io/imageio.cpp
  io/lipsyncformats.h io/lipsyncformats.cpp
  io/textgrid.h io/textgrid.cpp)
