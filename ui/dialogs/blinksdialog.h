#pragma once

#include "document/animation.h"

#include <QDialog>

class QLabel;
class QRadioButton;
class QSpinBox;

namespace toonface {

class Document;
class SecondsBox;

// Add Blinks…: human-like blinks (Timeline::randomBlinks) from a seed, over the whole
// animation or a range, replacing the blinks already there. One undo step on OK.
class BlinksDialog : public QDialog
{
    Q_OBJECT

public:
    // Opens the dialog modally; true when blinks were added.
    static bool run(QWidget *parent, Document *document);

    explicit BlinksDialog(Document *document, QWidget *parent = nullptr);

    quint32 seed() const;
    void setSeed(quint32 seed);
    // Blinks over [start, end) only (otherwise the whole animation).
    void setRange(double start, double end);
    double rangeStart() const;
    double rangeEnd() const;
    // The animation OK would make.
    Animation resultingAnimation() const;

public Q_SLOTS:
    void accept() override;
    // A new random seed.
    void shuffle();

private:
    void updateSummary();

    Document *m_document;
    QSpinBox *m_seed;
    QRadioButton *m_whole;
    QRadioButton *m_part;
    SecondsBox *m_start;
    SecondsBox *m_end;
    QLabel *m_summary;
};

} // namespace toonface
