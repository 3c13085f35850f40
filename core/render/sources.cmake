list(APPEND TOONFACE_CORE_SOURCES
  render/videoencoder.h render/videoencoder.cpp)
