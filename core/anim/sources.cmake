list(APPEND TOONFACE_CORE_SOURCES
  anim/easing.h
  anim/keycurve.h
  anim/timeline.h anim/timeline.cpp anim/timelinejson.cpp
  anim/timelineevaluator.h anim/timelineevaluator.cpp)
