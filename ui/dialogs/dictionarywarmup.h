#pragma once

#include <QObject>

namespace toonface {

// The character dictionary's first load (up to a second when its cache must be built) runs
// off the GUI thread: a dialog that reads scripts makes one of these, asks ready() before it
// parses a script, and checks again on loaded().
class DictionaryWarmUp : public QObject
{
    Q_OBJECT

public:
    // Starts the load in the background unless it is done already.
    explicit DictionaryWarmUp(QObject *parent = nullptr);

    bool ready() const; // parsing a script now will not wait for the dictionary

Q_SIGNALS:
    void loaded(); // the background load finished (once; never when ready at construction)
};

} // namespace toonface
