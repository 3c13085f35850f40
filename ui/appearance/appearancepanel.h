#pragma once

#include "document/document.h"

#include <QWidget>

#include <functional>

class QCheckBox;
class QComboBox;
class QPushButton;
class QSlider;
class QDoubleSpinBox;
class QLabel;

namespace toonface {

// The appearance of the cartoon beside the preview: the style's variants (eyebrows, nose, cute),
// the caricature factor, what the person wears (glasses and their shape, moustache, beard, hat,
// bald head), each component's fill, stroke and line weight, and resampling the colours from the
// photo. Every change is one Document::changeStyle step (a slider drag is one step, on release);
// the panel reads everything back from the document on each style change, holding no copy.
class AppearancePanel : public QWidget
{
    Q_OBJECT

public:
    explicit AppearancePanel(Document *document, QWidget *parent = nullptr);

    // The components the panel lists, with their labels: (style key, label) in display order.
    static QList<std::pair<QString, QString>> componentKeys();

private:
    void onDocumentChanged(ChangeFlags what);
    void sync();
    void change(const QString &text, const std::function<void(Style &)> &edit);
    void pickColour(const QString &key, bool stroke);
    QWidget *buildComponents();

    Document *m_document;
    QComboBox *m_eyebrows;
    QComboBox *m_nose;
    QCheckBox *m_cute;
    QSlider *m_caricature;
    QLabel *m_caricatureValue;
    QComboBox *m_glasses;
    QComboBox *m_age; // the age group drawn (render/agestyle.h): the photo's guess until the user picks
    QCheckBox *m_moustache;
    QCheckBox *m_beard;
    QCheckBox *m_goatee;
    QCheckBox *m_hat;
    QCheckBox *m_bald;
    QPushButton *m_resample;
    struct Row
    {
        QString key;
        QCheckBox *visible;
        QPushButton *fill;
        QPushButton *stroke;
        QDoubleSpinBox *width;
    };
    QList<Row> m_rows;
    bool m_syncing = false;
};

} // namespace toonface
