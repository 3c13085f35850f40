list(APPEND TOONFACE_CORE_SOURCES
  render/curves.h render/curves.cpp
  render/style.h render/style.cpp
  render/svgface.h render/svgface.cpp
  render/svgfacebuild.h render/svgfacebuild.cpp
  render/svgparts.h
  render/svgfeatures.h render/svgfeatures.cpp
  render/svgexpression.h render/svgexpression.cpp
  render/agestyle.h render/agestyle.cpp
  render/svgbody.h render/svgbody.cpp
  render/svgallowlist.h render/svgallowlist.cpp
  render/svglayer.h render/svglayer.cpp)
