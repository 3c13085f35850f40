#include "dialogs/blinksdialog.h"

#include "dialogs/animationedits.h"
#include "dialogs/secondsbox.h"
#include "document/document.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QRandomGenerator>
#include <QSpinBox>
#include <QVBoxLayout>

#include <limits>

namespace toonface {

namespace {

// A range for an animation with nothing on it yet.
constexpr double kEmptyAnimationRange = 10.0;

} // namespace

bool BlinksDialog::run(QWidget *parent, Document *document)
{
    BlinksDialog dialog(document, parent);
    return dialog.exec() == QDialog::Accepted;
}

BlinksDialog::BlinksDialog(Document *document, QWidget *parent)
    : QDialog(parent)
    , m_document(document)
    , m_seed(new QSpinBox(this))
    , m_whole(new QRadioButton(this))
    , m_part(new QRadioButton(tr("&From"), this))
    , m_start(new SecondsBox(this))
    , m_end(new SecondsBox(this))
    , m_summary(new QLabel(this))
{
    setWindowTitle(tr("Add Blinks"));

    auto *intro = new QLabel(tr("Blinks at a person's pace: about one every three and a half seconds, now and then "
                                "two in a row. The same pattern number always gives the same blinks."),
        this);
    intro->setWordWrap(true);

    m_seed->setObjectName(QStringLiteral("seed"));
    m_seed->setRange(0, std::numeric_limits<int>::max());
    auto *shuffleButton
        = new QPushButton(QIcon::fromTheme(QStringLiteral("media-playlist-shuffle")), tr("&Shuffle"), this);
    shuffleButton->setObjectName(QStringLiteral("shuffle"));
    auto *seedRow = new QHBoxLayout;
    seedRow->addWidget(m_seed, 1);
    seedRow->addWidget(shuffleButton);

    const double duration = m_document->timeline().duration();
    m_whole->setObjectName(QStringLiteral("whole"));
    m_whole->setText(tr("The &whole animation (%1 s)").arg(duration, 0, 'f', 2));
    m_whole->setEnabled(duration > 0);
    m_part->setObjectName(QStringLiteral("part"));
    m_start->setObjectName(QStringLiteral("start"));
    m_end->setObjectName(QStringLiteral("end"));
    m_end->setValue(duration > 0 ? duration : kEmptyAnimationRange);
    auto *partRow = new QHBoxLayout;
    partRow->addWidget(m_part);
    partRow->addWidget(m_start);
    partRow->addWidget(new QLabel(tr("to"), this));
    partRow->addWidget(m_end);
    partRow->addStretch(1);
    auto *overBox = new QVBoxLayout;
    overBox->addWidget(m_whole);
    overBox->addLayout(partRow);

    m_summary->setObjectName(QStringLiteral("summary"));
    m_summary->setWordWrap(true);

    auto *form = new QFormLayout;
    form->addRow(tr("&Pattern:"), seedRow);
    form->addRow(tr("Over:"), overBox);
    static_cast<QLabel *>(form->labelForField(seedRow))->setBuddy(m_seed);

    auto *buttons = new QDialogButtonBox(this);
    buttons->addButton(tr("Add Blinks"), QDialogButtonBox::AcceptRole)->setObjectName(QStringLiteral("ok"));
    buttons->addButton(QDialogButtonBox::Cancel);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(intro);
    layout->addLayout(form);
    layout->addWidget(m_summary);
    layout->addStretch(1);
    layout->addWidget(buttons);

    (duration > 0 ? m_whole : m_part)->setChecked(true);
    m_seed->setValue(int(QRandomGenerator::global()->bounded(100000)));

    connect(shuffleButton, &QPushButton::clicked, this, &BlinksDialog::shuffle);
    connect(m_seed, &QSpinBox::valueChanged, this, &BlinksDialog::updateSummary);
    connect(m_whole, &QRadioButton::toggled, this, &BlinksDialog::updateSummary);
    connect(m_start, &QDoubleSpinBox::valueChanged, this, [this] {
        m_part->setChecked(true);
        updateSummary();
    });
    connect(m_end, &QDoubleSpinBox::valueChanged, this, [this] {
        m_part->setChecked(true);
        updateSummary();
    });
    connect(buttons, &QDialogButtonBox::accepted, this, &BlinksDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &BlinksDialog::reject);
    updateSummary();
}

quint32 BlinksDialog::seed() const
{
    return quint32(m_seed->value());
}

void BlinksDialog::setSeed(quint32 seed)
{
    m_seed->setValue(int(std::min<quint32>(seed, quint32(std::numeric_limits<int>::max()))));
}

void BlinksDialog::setRange(double start, double end)
{
    m_start->setValue(start);
    m_end->setValue(end);
    m_part->setChecked(true);
    updateSummary();
}

double BlinksDialog::rangeStart() const
{
    return m_whole->isChecked() ? 0.0 : m_start->value();
}

double BlinksDialog::rangeEnd() const
{
    return m_whole->isChecked() ? m_document->timeline().duration() : m_end->value();
}

Animation BlinksDialog::resultingAnimation() const
{
    if (rangeEnd() <= rangeStart())
        return m_document->animation();
    return withBlinks(m_document->animation(), seed(), rangeStart(), rangeEnd());
}

void BlinksDialog::shuffle()
{
    m_seed->setValue(int(QRandomGenerator::global()->bounded(100000)));
}

void BlinksDialog::updateSummary()
{
    if (rangeEnd() <= rangeStart()) {
        m_summary->setText(tr("The range ends before it starts."));
        return;
    }
    int replaced = 0;
    for (const BlinkEvent &b : m_document->timeline().blinks())
        replaced += b.time >= rangeStart() && b.time < rangeEnd();
    int made = 0;
    const Animation after = resultingAnimation();
    for (const BlinkEvent &b : after.timeline.blinks())
        made += b.time >= rangeStart() && b.time < rangeEnd();
    const QString from = QString::number(rangeStart(), 'f', 2);
    const QString to = QString::number(rangeEnd(), 'f', 2);
    QString text = tr("%n blink(s) from %1 s to %2 s.", nullptr, made).arg(from, to);
    if (replaced > 0)
        text += QLatin1Char(' ') + tr("The %n blink(s) there now are replaced.", nullptr, replaced);
    m_summary->setText(text);
}

void BlinksDialog::accept()
{
    if (rangeEnd() <= rangeStart())
        return;
    m_document->changeAnimation(resultingAnimation(), tr("Add Blinks"));
    QDialog::accept();
}

} // namespace toonface
