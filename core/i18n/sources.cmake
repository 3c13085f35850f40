list(APPEND TOONFACE_CORE_SOURCES
  i18n/coretext.h i18n/translations.h i18n/translations.cpp)
