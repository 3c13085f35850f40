list(APPEND TOONFACE_CORE_SOURCES
  media/ffmpegutil.h media/ffmpegutil.cpp
  media/audiosource.h
  media/audiofeed.h media/audiofeed.cpp
  media/soundcopy.h media/soundcopy.cpp
  media/soundcheck.h media/soundcheck.cpp
  media/pngframes.h
  media/userfile.h media/userfile.cpp
  media/mediareader.h media/mediareader.cpp
  media/audiomix.h media/audiomix.cpp)
