#include "dialogs/shortcutsdialog.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace toonface {

namespace {

QString plainText(const QAction *action)
{
    QString text = action->text();
    text.remove(QRegularExpression(QStringLiteral("&(?!&)")));
    text.remove(QStringLiteral("…"));
    return text;
}

// The menu's commands that have a key, its submenus' under them.
void addMenu(QTreeWidgetItem *parent, const QMenu *menu)
{
    for (QAction *action : menu->actions()) {
        if (action->menu()) {
            auto *sub = new QTreeWidgetItem(parent, {plainText(action)});
            addMenu(sub, action->menu());
            if (sub->childCount() == 0)
                delete sub;
            continue;
        }
        if (action->isSeparator() || action->shortcuts().isEmpty())
            continue;
        QStringList keys;
        for (const QKeySequence &key : action->shortcuts())
            keys.append(key.toString(QKeySequence::NativeText));
        new QTreeWidgetItem(parent, {plainText(action), keys.join(QStringLiteral(", "))});
    }
}

} // namespace

ShortcutsDialog::ShortcutsDialog(const QMenuBar *menus, QWidget *parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("shortcutsDialog"));
    setWindowTitle(tr("Keyboard Shortcuts"));
    auto *tree = new QTreeWidget;
    tree->setObjectName(QStringLiteral("shortcuts"));
    tree->setHeaderLabels({tr("Command"), tr("Keys")});
    tree->setRootIsDecorated(true);
    for (QAction *action : menus->actions()) {
        if (!action->menu())
            continue;
        auto *top = new QTreeWidgetItem(tree, {plainText(action)});
        addMenu(top, action->menu());
        if (top->childCount() == 0)
            delete top;
    }
    // The timeline's keys no menu lists.
    auto *timeline = new QTreeWidgetItem(tree, {tr("Timeline (while it has focus)")});
    const std::pair<QString, QString> keys[] = {
        {tr("Set or insert a mouth shape"), QStringLiteral("M F H A I U E O N")},
        {tr("Zoom in, out, to fit"), QStringLiteral("=  -  \\")},
        {tr("Zoom about the pointer"), tr("Ctrl+wheel")},
        {tr("Scroll the rows"), tr("Shift+wheel")},
        {tr("Waveform taller or shorter"), tr("Alt+wheel")},
        {tr("Edit a syllable's pinyin"), tr("Double-click")},
    };
    for (const auto &[what, key] : keys)
        new QTreeWidgetItem(timeline, {what, key});
    tree->expandAll();
    tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(tree);
    layout->addWidget(buttons);
    resize(520, 560);
}

} // namespace toonface
