list(APPEND TOONFACE_CORE_SOURCES
  speech/progress.h
  speech/audio.h speech/audio.cpp
  speech/pinyin.h speech/pinyin.cpp
  speech/pinyindictionary.h speech/pinyindictionary.cpp
  speech/zhuyin.h speech/zhuyin.cpp
  speech/script.h speech/script.cpp
  speech/tts.h speech/tts.cpp
  speech/features.h speech/features.cpp
  speech/dtw.h speech/dtw.cpp
  speech/onsetsignals.h speech/onsetsignals.cpp
  speech/aligner.h speech/aligner.cpp
  speech/englishshapes.h speech/englishshapes.cpp
  speech/lipsync.h speech/lipsync.cpp
  speech/syllableshapes.h speech/syllableshapes.cpp
  speech/syllableduration.h speech/syllableduration.cpp
  speech/pinyinindex.h speech/pinyinindex.cpp
  speech/waveformpeaks.h speech/waveformpeaks.cpp)
