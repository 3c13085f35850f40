list(APPEND TOONFACE_CORE_SOURCES
  export/animationexport.h export/animationexport.cpp
  export/partfiles.h export/partfiles.cpp
  export/cartoonfile.h export/cartoonfile.cpp
  export/framerenderer.h export/framerenderer.cpp
  export/videoencoder.h export/videoencoder.cpp
  export/videosink.h export/muxedsink.cpp export/mp4sink.cpp export/gifsink.cpp export/pngsink.cpp
  export/alphasink.cpp
  export/exportbackground.h export/exportbackground.cpp
  export/exportpreset.h export/exportpreset.cpp
  export/keptframes.h export/keptframes.cpp
  export/smilexport.h export/smilexport.cpp export/smilutil.h
  export/smilchannels.h export/smilchannels.cpp
  export/smilkeys.h export/smilkeys.cpp
  export/smilreduce.h export/smilreduce.cpp
  export/smilscale.h export/smilscale.cpp
  export/smilhidden.h export/smilhidden.cpp
  export/smilaudio.h export/smilaudio.cpp
  export/svgnumbers.h export/svgnumbers.cpp
  export/svgxml.h export/svgxml.cpp
  export/htmlplayer.h export/htmlplayer.cpp
  export/epubbook.h export/epubbook.cpp export/epubdocs.h export/epubdocs.cpp
  export/epubtext.h export/epubtext.cpp export/epubzip.h export/epubzip.cpp
  export/bookvideo.h export/bookvideo.cpp)
