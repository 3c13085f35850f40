list(APPEND TOONFACE_CORE_SOURCES
  track/framesource.h
  track/clocksource.h track/clocksource.cpp
  track/videofilesource.h track/videofilesource.cpp
  track/oneeuro.h
  track/facemeasure.h track/facemeasure.cpp
  track/trackingmethod.h track/landmarkmethod.cpp track/classicmethod.cpp
  track/facesearch.h track/facesearch.cpp
  track/tracker.h track/tracker.cpp
  track/trackvideo.h track/trackvideo.cpp
  track/mouthrange.h track/mouthrange.cpp
  track/clipsilence.h track/clipsilence.cpp
  track/neutralchoice.h track/neutralchoice.cpp
  track/retarget.h track/retarget.cpp
  track/livepose.h track/livepose.cpp
  track/trackaccuracy.h track/trackaccuracy.cpp)
# The landmark fit runs every frame: optimised in Debug builds too (as detect/).
set_source_files_properties(track/landmarkmethod.cpp track/facemeasure.cpp PROPERTIES COMPILE_OPTIONS "-O2")
