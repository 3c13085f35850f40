#include "dialogs/dictionarywarmup.h"

#include "speech/pinyindictionary.h"

#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

namespace toonface {

DictionaryWarmUp::DictionaryWarmUp(QObject *parent)
    : QObject(parent)
{
    if (ready())
        return;
    auto *watcher = new QFutureWatcher<void>(this);
    connect(watcher, &QFutureWatcher<void>::finished, this, &DictionaryWarmUp::loaded);
    watcher->setFuture(QtConcurrent::run([] { PinyinDictionary::shared(); }));
}

bool DictionaryWarmUp::ready() const
{
    return PinyinDictionary::isLoaded();
}

} // namespace toonface
