#pragma once

#include <QDialog>

class QComboBox;
class QLabel;

namespace toonface {

// Edit ▸ Preferences…: the interface's language (System, English, 繁體中文, 简体中文), stored in
// Settings and applied when Toonface next starts (the note says so when it differs from the
// language running now).
class PreferencesDialog : public QDialog
{
    Q_OBJECT

public:
    // Opens the dialog modally; true when the choices were stored.
    static bool run(QWidget *parent);

    // `running` is the translation the interface shows now ("", "zh_TW", "zh_CN").
    explicit PreferencesDialog(const QString &running, QWidget *parent = nullptr);

    // The chosen setting: "", "en", "zh_TW" or "zh_CN".
    QString language() const;
    void setLanguage(const QString &language);
    // Whether the note "applies on restart" shows (the choice differs from the running language).
    bool restartNeeded() const;

public Q_SLOTS:
    void accept() override;

private:
    void updateNote();

    QString m_running;
    QComboBox *m_language;
    QLabel *m_note;
};

} // namespace toonface
