list(APPEND TOONFACE_CORE_SOURCES
  export/videoencoder.h export/videoencoder.cpp
  export/smilexport.h export/smilexport.cpp
  export/htmlplayer.h export/htmlplayer.cpp
  export/framerenderer.h export/framerenderer.cpp)
