#include "dialogs/jobstatus.h"

#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>
#include <QStyle>

#include <algorithm>

namespace toonface {

namespace {

constexpr int kProgressSteps = 1000;

} // namespace

JobStatus::JobStatus(QWidget *parent)
    : QWidget(parent)
    , m_progress(new QProgressBar(this))
    , m_stage(new QLabel(this))
    , m_icon(new QLabel(this))
    , m_message(new QLabel(this))
{
    m_progress->setObjectName(QStringLiteral("progress"));
    m_progress->setRange(0, kProgressSteps);
    m_progress->setTextVisible(true);
    m_stage->setObjectName(QStringLiteral("stage"));
    m_message->setObjectName(QStringLiteral("message"));
    m_message->setWordWrap(true);
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
    m_message->clear();
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
    m_message->clear();
    m_message->hide();
    m_error = false;
}

QString JobStatus::message() const
{
    return m_message->text();
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
    m_message->setText(message);
    m_message->show();
}

} // namespace toonface
