#pragma once

#include "document/document.h"

#include <QWidget>

#include <functional>

class QCheckBox;
class QDoubleSpinBox;
class QListWidget;
class QPushButton;

namespace toonface {

// The user's own SVG layers of the style (clothing, accessories: thesis Fig. 7.9), in the
// appearance dock: add from files, remove, reorder, hide, and place the selected one (its centre
// from the face's centre and its width, in eye distances; in front of the face or behind it).
// Every change is one Document::changeStyle step; the list reads everything back from the
// document on each style change.
class LayersEditor : public QWidget
{
    Q_OBJECT

public:
    explicit LayersEditor(Document *document, QWidget *parent = nullptr);

    // Adds the SVG file as the last layer, in front of the face, one step. On a file that cannot
    // be read or is not SVG, returns false with *error naming the file, and changes nothing.
    bool addFile(const QString &path, QString *error);
    int currentLayer() const;
    void setCurrentLayer(int index);

private:
    void onDocumentChanged(ChangeFlags what);
    void sync();
    void chooseFiles();
    void change(const QString &text, const std::function<void(QVector<StyleLayer> &)> &edit, int select = -2);
    void move(int by);

    Document *m_document;
    QListWidget *m_list;
    QPushButton *m_add;
    QPushButton *m_remove;
    QPushButton *m_up;
    QPushButton *m_down;
    QDoubleSpinBox *m_x;
    QDoubleSpinBox *m_y;
    QDoubleSpinBox *m_width;
    QCheckBox *m_front;
    QCheckBox *m_follows;
    bool m_syncing = false;
};

} // namespace toonface
