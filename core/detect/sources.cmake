list(APPEND TOONFACE_CORE_SOURCES
  detect/landmarkmap.h detect/landmarkmap.cpp)
