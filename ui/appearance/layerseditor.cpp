#include "appearance/layerseditor.h"

#include "render/svglayer.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

namespace toonface {

LayersEditor::LayersEditor(Document *document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_list = new QListWidget;
    m_list->setObjectName(QStringLiteral("layers"));
    m_list->setToolTip(tr("Your own SVG drawings over or under the face, in drawing order; untick to hide"));
    m_list->setMaximumHeight(110);
    layout->addWidget(m_list);

    auto *buttons = new QHBoxLayout;
    m_add = new QPushButton(tr("Add…"));
    m_add->setObjectName(QStringLiteral("addLayer"));
    m_add->setToolTip(tr("Add a drawing from an SVG file (clothing, an accessory); the project keeps a copy"));
    m_remove = new QPushButton(tr("Remove"));
    m_remove->setObjectName(QStringLiteral("removeLayer"));
    m_up = new QPushButton(tr("Up"));
    m_up->setObjectName(QStringLiteral("layerUp"));
    m_up->setToolTip(tr("Draw earlier (further back)"));
    m_down = new QPushButton(tr("Down"));
    m_down->setObjectName(QStringLiteral("layerDown"));
    m_down->setToolTip(tr("Draw later (further forward)"));
    for (QPushButton *b : {m_add, m_remove, m_up, m_down})
        buttons->addWidget(b);
    layout->addLayout(buttons);

    auto *form = new QFormLayout;
    auto spin = [](const char *name, double min, double max, const QString &tip) {
        auto *s = new QDoubleSpinBox;
        s->setObjectName(QLatin1StringView(name));
        s->setRange(min, max);
        s->setSingleStep(0.05);
        s->setDecimals(2);
        s->setToolTip(tip);
        return s;
    };
    m_x = spin("layerX", -20, 20, tr("Across from the face's centre, in eye distances (right is positive)"));
    m_y = spin("layerY", -20, 20, tr("Down from the face's centre, in eye distances"));
    m_width = spin("layerWidth", 0.05, 20, tr("The drawing's width, in eye distances"));
    m_front = new QCheckBox(tr("In front of the face"));
    m_front->setObjectName(QStringLiteral("layerFront"));
    m_front->setToolTip(tr("Unticked, the drawing lies behind the head, over the neck and shoulders"));
    m_follows = new QCheckBox(tr("Moves with the head"));
    m_follows->setObjectName(QStringLiteral("layerFollowsHead"));
    m_follows->setToolTip(tr("Ticked, the drawing moves, turns and nods with the head (a hat, glasses, earrings); "
                             "unticked, it stays still as the head moves (clothes)"));
    auto *position = new QHBoxLayout;
    position->addWidget(m_x);
    position->addWidget(m_y);
    form->addRow(tr("Position:"), position);
    form->addRow(tr("Width:"), m_width);
    form->addRow(QString(), m_front);
    form->addRow(QString(), m_follows);
    layout->addLayout(form);

    connect(m_add, &QPushButton::clicked, this, &LayersEditor::chooseFiles);
    connect(m_remove, &QPushButton::clicked, this, [this] {
        const int i = currentLayer();
        if (i >= 0)
            change(
                tr("Remove layer"), [&](QVector<StyleLayer> &l) { l.removeAt(i); },
                std::min(i, int(m_list->count()) - 2));
    });
    connect(m_up, &QPushButton::clicked, this, [this] { move(-1); });
    connect(m_down, &QPushButton::clicked, this, [this] { move(1); });
    connect(m_list, &QListWidget::itemChanged, this, [this](QListWidgetItem *item) {
        const int i = m_list->row(item);
        const bool on = item->checkState() == Qt::Checked;
        change(
            on ? tr("Show layer") : tr("Hide layer"), [&](QVector<StyleLayer> &l) { l[i].visible = on; }, i);
    });
    connect(m_list, &QListWidget::currentRowChanged, this, [this] {
        if (!m_syncing)
            sync();
    });
    auto placed
        = [this](QDoubleSpinBox *box, const QString &text, const std::function<void(StyleLayer &, double)> &set) {
              connect(box, &QDoubleSpinBox::editingFinished, this, [this, box, text, set] {
                  const int i = currentLayer();
                  if (i >= 0)
                      change(
                          text, [&](QVector<StyleLayer> &l) { set(l[i], box->value()); }, i);
              });
          };
    placed(m_x, tr("Move layer"), [](StyleLayer &l, double v) { l.offset.setX(v); });
    placed(m_y, tr("Move layer"), [](StyleLayer &l, double v) { l.offset.setY(v); });
    placed(m_width, tr("Resize layer"), [](StyleLayer &l, double v) { l.width = v; });
    connect(m_front, &QCheckBox::clicked, this, [this](bool on) {
        const int i = currentLayer();
        if (i >= 0)
            change(
                on ? tr("Layer in front") : tr("Layer behind"), [&](QVector<StyleLayer> &l) { l[i].front = on; }, i);
    });
    connect(m_follows, &QCheckBox::clicked, this, [this](bool on) {
        const int i = currentLayer();
        if (i >= 0)
            change(
                on ? tr("Layer follows the head") : tr("Layer stays still"),
                [&](QVector<StyleLayer> &l) { l[i].followsHead = on; }, i);
    });
    connect(m_document, &Document::changed, this, &LayersEditor::onDocumentChanged);
    sync();
}

int LayersEditor::currentLayer() const
{
    return m_list->currentRow();
}

void LayersEditor::setCurrentLayer(int index)
{
    m_list->setCurrentRow(index);
}

bool LayersEditor::addFile(const QString &path, QString *error)
{
    if (!m_document->hasFace()) {
        *error = tr("There is no face to place %1 on.").arg(path);
        return false;
    }
    StyleLayer layer;
    if (!loadLayerFile(path, &layer, error))
        return false;
    const int index = int(m_document->style().layers.size());
    change(
        tr("Add layer %1").arg(layer.name), [&](QVector<StyleLayer> &l) { l.append(layer); }, index);
    return true;
}

void LayersEditor::chooseFiles()
{
    const QStringList files
        = QFileDialog::getOpenFileNames(this, tr("Add layers"), QString(), tr("SVG drawings (*.svg);;All files (*)"));
    for (const QString &file : files) {
        QString error;
        if (!addFile(file, &error))
            QMessageBox::warning(this, tr("Add layer"), error);
    }
}

void LayersEditor::move(int by)
{
    const int i = currentLayer();
    const int j = i + by;
    if (i < 0 || j < 0 || j >= m_list->count())
        return;
    change(
        tr("Reorder layers"), [&](QVector<StyleLayer> &l) { l.swapItemsAt(i, j); }, j);
}

void LayersEditor::change(const QString &text, const std::function<void(QVector<StyleLayer> &)> &edit, int select)
{
    if (m_syncing || !m_document->hasFace())
        return;
    Style style = m_document->style();
    edit(style.layers);
    if (style == m_document->style())
        return;
    if (select != -2)
        m_list->setProperty("pendingRow", select);
    m_document->changeStyle(style, text);
}

void LayersEditor::onDocumentChanged(ChangeFlags what)
{
    if (what & (Change::Style | Change::Face))
        sync();
}

void LayersEditor::sync()
{
    m_syncing = true;
    const QVector<StyleLayer> &layers = m_document->style().layers;
    int row = m_list->currentRow();
    if (const QVariant pending = m_list->property("pendingRow"); pending.isValid()) {
        row = pending.toInt();
        m_list->setProperty("pendingRow", QVariant());
    }
    if (m_list->count() != layers.size()) {
        m_list->clear();
        for (qsizetype i = 0; i < layers.size(); ++i)
            m_list->addItem(new QListWidgetItem);
    }
    for (qsizetype i = 0; i < layers.size(); ++i) {
        QListWidgetItem *item = m_list->item(int(i));
        item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        item->setText(layers[i].front ? layers[i].name : tr("%1 (behind)").arg(layers[i].name));
        item->setCheckState(layers[i].visible ? Qt::Checked : Qt::Unchecked);
    }
    row = std::clamp(row, layers.isEmpty() ? -1 : 0, int(layers.size()) - 1);
    m_list->setCurrentRow(row);
    const bool has = row >= 0;
    setEnabled(m_document->hasFace());
    for (QWidget *w : std::initializer_list<QWidget *> {m_remove, m_x, m_y, m_width, m_front, m_follows})
        w->setEnabled(has);
    m_up->setEnabled(has && row > 0);
    m_down->setEnabled(has && row + 1 < layers.size());
    if (has) {
        const StyleLayer &l = layers[row];
        m_x->setValue(l.offset.x());
        m_y->setValue(l.offset.y());
        m_width->setValue(l.width);
        m_front->setChecked(l.front);
        m_follows->setChecked(l.followsHead);
    }
    m_syncing = false;
}

} // namespace toonface
