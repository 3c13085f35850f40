#pragma once

#include "anim/timeline.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QSlider;
class QSpinBox;

namespace toonface {

class Document;
class PosePreview;
class SecondsBox;

// Add Emotion…: one emotion clip (a preset, its range, intensity and fades) with a preview of
// this character wearing it. One undo step on OK; the emotions already under the clip give way
// unless the user asks to keep them (then the two add up).
class EmotionDialog : public QDialog
{
    Q_OBJECT

public:
    // Opens the dialog modally over [start, end] (end < 0: the whole animation); true when an
    // emotion was added.
    static bool run(QWidget *parent, Document *document, double start = 0, double end = -1);

    explicit EmotionDialog(Document *document, QWidget *parent = nullptr);

    void setClip(const EmotionClip &clip);
    EmotionClip clip() const;
    bool replacesOthers() const;

public Q_SLOTS:
    void accept() override;

private:
    void updatePreview();

    Document *m_document;
    QComboBox *m_emotion;
    SecondsBox *m_start;
    SecondsBox *m_end;
    QSlider *m_intensity;
    QSpinBox *m_intensityValue;
    SecondsBox *m_fadeIn;
    SecondsBox *m_fadeOut;
    QCheckBox *m_replace;
    PosePreview *m_preview;
};

} // namespace toonface
