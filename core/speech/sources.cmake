list(APPEND TOONFACE_CORE_SOURCES
  speech/pinyin.h speech/pinyin.cpp
  speech/syllableshapes.h speech/syllableshapes.cpp)
