list(APPEND TOONFACE_CORE_SOURCES
  render/curves.h render/curves.cpp
  render/style.h render/style.cpp
  render/svgface.h render/svgface.cpp)
