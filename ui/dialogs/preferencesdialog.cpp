#include "dialogs/preferencesdialog.h"

#include "i18n/translations.h"
#include "window/settings.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace toonface {

bool PreferencesDialog::run(QWidget *parent)
{
    PreferencesDialog dialog(installedTranslation(), parent);
    return dialog.exec() == QDialog::Accepted;
}

PreferencesDialog::PreferencesDialog(const QString &running, QWidget *parent)
    : QDialog(parent)
    , m_running(running)
{
    setWindowTitle(tr("Preferences"));
    m_language = new QComboBox;
    m_language->setObjectName(QStringLiteral("language"));
    // Each language by its own name, so a reader finds theirs whatever the interface shows.
    const QString system = translationForLocale(systemUiLocale());
    const QString systemName = system == QLatin1StringView("zh_TW") ? QStringLiteral("繁體中文")
        : system == QLatin1StringView("zh_CN")                      ? QStringLiteral("简体中文")
                                                                    : QStringLiteral("English");
    m_language->addItem(tr("System (%1)").arg(systemName), QString());
    m_language->addItem(QStringLiteral("English"), QStringLiteral("en"));
    m_language->addItem(QStringLiteral("繁體中文"), QStringLiteral("zh_TW"));
    m_language->addItem(QStringLiteral("简体中文"), QStringLiteral("zh_CN"));
    m_note = new QLabel(tr("The new language shows when Toonface is started again."));
    m_note->setObjectName(QStringLiteral("restartNote"));
    m_note->setWordWrap(true);
    // Room for the note on two lines at most, in any language.
    setMinimumWidth(fontMetrics().averageCharWidth() * 48);

    auto *form = new QFormLayout;
    form->addRow(tr("&Language:"), m_language);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &PreferencesDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &PreferencesDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_note);
    layout->addStretch();
    layout->addWidget(buttons);

    setLanguage(Settings().language());
    connect(m_language, &QComboBox::currentIndexChanged, this, &PreferencesDialog::updateNote);
    updateNote();
}

QString PreferencesDialog::language() const
{
    return m_language->currentData().toString();
}

void PreferencesDialog::setLanguage(const QString &language)
{
    const int index = m_language->findData(language);
    m_language->setCurrentIndex(index < 0 ? 0 : index);
}

bool PreferencesDialog::restartNeeded() const
{
    return translationForSetting(language()) != m_running;
}

void PreferencesDialog::updateNote()
{
    m_note->setVisible(restartNeeded());
}

void PreferencesDialog::accept()
{
    Settings settings;
    settings.setLanguage(language());
    settings.sync();
    QDialog::accept();
}

} // namespace toonface
