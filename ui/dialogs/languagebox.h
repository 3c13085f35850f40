#pragma once

#include "speech/script.h"

#include <QComboBox>

namespace toonface {

// The language of a script: detected from the script, Mandarin or English.
class LanguageBox : public QComboBox
{
    Q_OBJECT

public:
    explicit LanguageBox(QWidget *parent = nullptr);

    Language language() const;
    void setLanguage(Language language);
    // "cmn", "en"; anything else selects Auto.
    void setLanguageCode(const QString &code);
};

} // namespace toonface
