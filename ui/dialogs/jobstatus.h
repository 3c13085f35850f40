#pragma once

#include <QWidget>

class QLabel;
class QProgressBar;

namespace toonface {

class MessageLabel;

inline constexpr int kMessageLines = 4;

// The foot of a dialog that runs long work: a progress bar with what is being done while it
// runs, and afterwards a message (an error, or a note such as "cancelled") that stays until
// the next run. The message is selectable text, so the user can copy an error. A long message
// keeps to kMessageLines lines whatever the width (wrapped at words, or anywhere in a long
// path), its last line cut in the middle with "…" (the problem, at the end, stays in sight),
// whole in its tooltip: a word-wrapped label grew taller than the
// dialog's layout reckoned, and pushed the rows above it over each other.
class JobStatus : public QWidget
{
    Q_OBJECT

public:
    explicit JobStatus(QWidget *parent = nullptr);

    void showProgress(double fraction, const QString &stage);
    void showError(const QString &message);
    void showNote(const QString &message);
    void clear();

    // The message shown now (empty while running or when none).
    QString message() const;
    bool isError() const { return m_error; }

private:
    void showMessage(const QString &message, bool error);

    QProgressBar *m_progress;
    QLabel *m_stage;
    QLabel *m_icon;
    MessageLabel *m_message;
    bool m_error = false;
};

} // namespace toonface
