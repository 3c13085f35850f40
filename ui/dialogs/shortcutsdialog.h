#pragma once

#include <QDialog>

class QMenuBar;

namespace toonface {

// Help ▸ Keyboard Shortcuts: every command of the menus that has a key, menu by menu, as the
// menus hold them now (so it never goes stale), and the timeline's keys that no menu shows.
class ShortcutsDialog : public QDialog
{
    Q_OBJECT

public:
    ShortcutsDialog(const QMenuBar *menus, QWidget *parent = nullptr);
};

} // namespace toonface
