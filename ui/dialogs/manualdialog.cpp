#include "dialogs/manualdialog.h"

#include "i18n/translations.h"

#include <QDialogButtonBox>
#include <QFile>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace toonface {

QString ManualDialog::resourceFor(const QString &translation)
{
    const QString name = translation == QLatin1String("zh_TW") || translation == QLatin1String("zh_CN")
        ? translation
        : QStringLiteral("en");
    return QStringLiteral(":/toonface/manual/manual_%1.html").arg(name);
}

QString ManualDialog::html(const QString &translation)
{
    QFile file(resourceFor(translation));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(file.readAll());
}

ManualDialog::ManualDialog(QWidget *parent)
    : QDialog(parent)
    , m_browser(new QTextBrowser(this))
{
    setWindowTitle(tr("User Manual"));
    setObjectName(QStringLiteral("manualDialog"));
    m_browser->setObjectName(QStringLiteral("manual"));
    m_browser->setOpenExternalLinks(false);
    m_browser->setHtml(html(installedTranslation()));

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_browser, 1);
    layout->addWidget(buttons);
    resize(640, 560);
}

} // namespace toonface
