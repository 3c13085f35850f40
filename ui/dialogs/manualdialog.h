#pragma once

#include <QDialog>

class QTextBrowser;

namespace toonface {

// Help ▸ User Manual: the short manual of the four jobs (a photo and its points; lip sync and the
// timeline; a video and Live Mode; export), shipped in the program (resources/manual) in English,
// Traditional and Simplified Chinese, shown in the interface's language. Nothing is fetched.
class ManualDialog : public QDialog
{
    Q_OBJECT

public:
    explicit ManualDialog(QWidget *parent = nullptr);

    // The manual's resource for a translation ("zh_TW", "zh_CN"; "" or any other: English).
    static QString resourceFor(const QString &translation);
    // The manual's text as HTML for a translation; empty when the resource is missing.
    static QString html(const QString &translation);

    QTextBrowser *browser() const { return m_browser; }

private:
    QTextBrowser *m_browser;
};

} // namespace toonface
