list(APPEND TOONFACE_CORE_SOURCES
  speech/progress.h
  speech/stagetimes.h speech/stagetimes.cpp
  speech/audio.h speech/audio.cpp
  speech/audioconvert.h speech/wavfile.h speech/wavfile.cpp
  speech/audioffmpeg.cpp
  speech/pinyin.h speech/pinyin.cpp
  speech/pinyindictionary.h speech/pinyindictionary.cpp
  speech/zhuyin.h speech/zhuyin.cpp
  speech/script.h speech/script.cpp
  speech/tonesandhi.h speech/tonesandhi.cpp
  speech/tts.h speech/tts.cpp
  speech/ttsvoicefile.h speech/ttsvoicefile.cpp
  speech/realfft.h speech/realfft.cpp
  speech/features.h speech/features.cpp
  speech/localnorm.h speech/localnorm.cpp
  speech/dtw.h speech/dtw.cpp
  speech/onsetsignals.h speech/onsetsignals.cpp
  speech/rangemax.h
  speech/samplerelay.h speech/samplerelay.cpp
  speech/referencefeatures.h speech/referencefeatures.cpp
  speech/syllablesearch.h speech/syllablesearch.cpp
  speech/boundaryrefine.h speech/boundaryrefine.cpp
  speech/hiddeninitials.h speech/hiddeninitials.cpp
  speech/paceprobe.h speech/paceprobe.cpp
  speech/speakeradapt.h speech/speakeradapt.cpp
  speech/alignconfidence.h speech/alignconfidence.cpp
  speech/aligner.h speech/aligner.cpp
  speech/englishshapes.h speech/englishshapes.cpp
  speech/lipsync.h speech/lipsync.cpp
  speech/syllableshapes.h speech/syllableshapes.cpp
  speech/syllableduration.h speech/syllableduration.cpp
  speech/pinyinindex.h speech/pinyinindex.cpp
  speech/waveformpeaks.h speech/waveformpeaks.cpp
  speech/audiomouth.h speech/audiomouth.cpp)
