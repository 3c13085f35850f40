// A script as a user types or loads it: Chinese characters, pinyin, Zhuyin, a mix, or English.
// The first byte picks the language the user chose (auto, Mandarin, English); the rest is the
// text as UTF-8 (invalid sequences included). Every syllable read lies inside the text, and
// gets mouth shapes; a failed parse names a problem.

#include "fuzzinput.h"

#include "speech/script.h"
#include "speech/syllableshapes.h"

using namespace toonface;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const fuzz::Split in = fuzz::split(data, size);
    static constexpr Language kLanguages[] = {Language::Auto, Language::Mandarin, Language::English};
    const Language language = kLanguages[in.selector % 3];
    const QString text = QString::fromUtf8(reinterpret_cast<const char *>(in.data), qsizetype(in.size));
    const ScriptParse parse = parseScript(text, language);
    TOONFACE_FUZZ_CHECK(parse.ok() == parse.problems.isEmpty() || !parse.error.isEmpty());
    for (const ScriptSyllable &s : parse.script.syllables) {
        TOONFACE_FUZZ_CHECK(s.position >= 0 && s.length >= 0 && s.position + s.length <= text.size());
        if (parse.script.language == Language::Mandarin) {
            TOONFACE_FUZZ_CHECK(s.tone >= 1 && s.tone <= 5);
            syllableShapes(s.pinyin);
        }
    }
    return 0;
}
