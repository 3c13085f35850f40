#include "dialogs/jobstatus.h"

#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>
#include <QStyle>
#include <QTextLayout>

#include <algorithm>

namespace toonface {

namespace {

constexpr int kProgressSteps = 1000;

// The lines `text` wraps to at `width` (at words, else anywhere: a path has no spaces).
QStringList wrappedLines(const QString &text, const QFont &font, int width)
{
    QStringList lines;
    for (const QString &paragraph : text.split(QLatin1Char('\n'))) {
        QTextLayout layout(paragraph, font);
        QTextOption option;
        option.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
        layout.setTextOption(option);
        layout.beginLayout();
        for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
            line.setLineWidth(width);
            lines << paragraph.mid(line.textStart(), line.textLength()).trimmed();
        }
        layout.endLayout();
        if (paragraph.isEmpty())
            lines << QString();
    }
    return lines;
}

} // namespace

// The message, wrapped to the label's width by hand (so that its height is known to the
// layout whatever the width: it asks no heightForWidth) and cut to kMessageLines.
class MessageLabel : public QLabel
{
public:
    explicit MessageLabel(QWidget *parent)
        : QLabel(parent)
    {
        // As wide as the dialog makes it: a long line never widens the dialog.
        setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        setAlignment(Qt::AlignLeft | Qt::AlignTop);
        setTextFormat(Qt::PlainText); // a file name is never markup
    }

    void setMessage(const QString &message)
    {
        m_message = message;
        rewrap();
    }
    QString message() const { return m_message; }

protected:
    void resizeEvent(QResizeEvent *event) override
    {
        QLabel::resizeEvent(event);
        rewrap();
    }

private:
    void rewrap()
    {
        const int width = std::max(1, contentsRect().width());
        QStringList lines = wrappedLines(m_message, font(), width);
        const bool cut = lines.size() > kMessageLines;
        if (cut) {
            // The last line shown carries the rest, cut in its middle: the end of a message
            // says the problem ("…/clip.mp4: no such file").
            const QString rest = lines.mid(kMessageLines - 1).join(QLatin1Char(' '));
            lines = lines.mid(0, kMessageLines - 1);
            lines << fontMetrics().elidedText(rest, Qt::ElideMiddle, width);
        }
        if (m_message.isEmpty())
            lines.clear();
        const QString shown = lines.join(QLatin1Char('\n'));
        if (shown != text())
            setText(shown);
        setToolTip(cut ? m_message : QString());
        const int height = int(lines.size()) * fontMetrics().lineSpacing();
        if (height != minimumHeight())
            setFixedHeight(height);
    }

    QString m_message;
};

JobStatus::JobStatus(QWidget *parent)
    : QWidget(parent)
    , m_progress(new QProgressBar(this))
    , m_stage(new QLabel(this))
    , m_icon(new QLabel(this))
    , m_message(new MessageLabel(this))
{
    m_progress->setObjectName(QStringLiteral("progress"));
    m_progress->setRange(0, kProgressSteps);
    m_progress->setTextVisible(true);
    m_stage->setObjectName(QStringLiteral("stage"));
    m_message->setObjectName(QStringLiteral("message"));
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_icon->setAlignment(Qt::AlignTop);

    auto *layout = new QGridLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_progress, 0, 0, 1, 2);
    layout->addWidget(m_stage, 1, 0, 1, 2);
    layout->addWidget(m_icon, 2, 0);
    layout->addWidget(m_message, 2, 1);
    layout->setColumnStretch(1, 1);
    clear();
}

void JobStatus::showProgress(double fraction, const QString &stage)
{
    m_icon->hide();
    m_message->setMessage(QString());
    m_message->hide();
    m_error = false;
    m_progress->show();
    m_progress->setValue(int(std::clamp(fraction, 0.0, 1.0) * kProgressSteps));
    m_stage->setText(stage);
    m_stage->show();
}

void JobStatus::showError(const QString &message)
{
    showMessage(message, true);
}

void JobStatus::showNote(const QString &message)
{
    showMessage(message, false);
}

void JobStatus::clear()
{
    m_progress->hide();
    m_stage->hide();
    m_icon->hide();
    m_message->setMessage(QString());
    m_message->hide();
    m_error = false;
}

QString JobStatus::message() const
{
    return m_message->message();
}

void JobStatus::showMessage(const QString &message, bool error)
{
    m_progress->hide();
    m_stage->hide();
    m_error = error;
    const int size = style()->pixelMetric(QStyle::PM_SmallIconSize, nullptr, this);
    m_icon->setPixmap(
        style()
            ->standardIcon(error ? QStyle::SP_MessageBoxWarning : QStyle::SP_MessageBoxInformation, nullptr, this)
            .pixmap(size, size));
    m_icon->show();
    m_message->setMessage(message);
    m_message->show();
}

} // namespace toonface
