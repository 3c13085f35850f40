#include "dialogs/languagebox.h"

namespace toonface {

LanguageBox::LanguageBox(QWidget *parent)
    : QComboBox(parent)
{
    addItem(tr("Detect from the script"), int(Language::Auto));
    addItem(tr("Mandarin (普通话)"), int(Language::Mandarin));
    addItem(tr("English"), int(Language::English));
}

Language LanguageBox::language() const
{
    return Language(currentData().toInt());
}

void LanguageBox::setLanguage(Language language)
{
    setCurrentIndex(std::max(0, findData(int(language))));
}

void LanguageBox::setLanguageCode(const QString &code)
{
    const std::optional<Language> language = languageFromCode(code);
    setLanguage(language ? *language : Language::Auto);
}

} // namespace toonface
