#include "document/autosaver.h"

#include "document/document.h"
#include "document/loadedfile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QStandardPaths>
#include <QUuid>

#include <algorithm>

namespace toonface {

namespace {

const QLatin1StringView kRecoveryPrefix("recovery-");
const QLatin1StringView kProjectSuffix(".toonface");
const QLatin1StringView kInfoSuffix(".json");
const QLatin1StringView kLockSuffix(".lock");

QString stemOf(const QString &recoveryPath)
{
    QString stem = recoveryPath;
    stem.chop(kProjectSuffix.size());
    return stem;
}

} // namespace

Autosaver::Autosaver(Document *document, const QString &directory, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_directory(directory)
{
    QDir().mkpath(m_directory);
    // A random part keeps the name unique even when the system reuses a crashed editor's pid.
    const QString stem = QDir(m_directory)
                             .filePath(kRecoveryPrefix + QString::number(QCoreApplication::applicationPid())
                                 + QLatin1Char('-') + QUuid::createUuid().toString(QUuid::Id128).left(8));
    m_recoveryPath = stem + kProjectSuffix;
    m_lock = std::make_unique<QLockFile>(stem + kLockSuffix);
    m_lock->setStaleLockTime(0); // held for the editor's whole life: stale only when its owner is gone
    m_lock->tryLock(0);

    m_timer.setTimerType(Qt::VeryCoarseTimer);
    connect(&m_timer, &QTimer::timeout, this, &Autosaver::onTimeout);
    connect(m_document, &Document::changed, this, [this](ChangeFlags what) {
        if (what.testFlag(Change::FileState) && !m_document->isModified())
            discard();
    });
}

Autosaver::~Autosaver() = default;

void Autosaver::setInterval(int seconds)
{
    if (seconds <= 0) {
        m_timer.stop();
        return;
    }
    m_timer.start(seconds * 1000);
}

int Autosaver::interval() const
{
    return m_timer.isActive() ? m_timer.interval() / 1000 : 0;
}

bool Autosaver::autosave(QString *error)
{
    if (!m_document->isModified() || !m_document->hasFace() || m_document->revision() == m_writtenRevision)
        return true;

    QJsonObject info;
    info.insert(QStringLiteral("originalPath"), m_document->filePath());
    info.insert(QStringLiteral("written"), QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs));
    QSaveFile infoFile(infoPath());
    QString message;
    if (!infoFile.open(QIODevice::WriteOnly) || infoFile.write(QJsonDocument(info).toJson()) < 0
        || !infoFile.commit()) {
        message = tr("%1: cannot write the recovery file: %2").arg(infoPath(), infoFile.errorString());
    } else if (!saveProject(m_document->project(), m_recoveryPath, &message)) {
        if (message.isEmpty())
            message = tr("%1: cannot write the recovery file").arg(m_recoveryPath);
    }
    if (!message.isEmpty()) {
        if (error)
            *error = message;
        Q_EMIT failed(message);
        return false;
    }
    m_writtenRevision = m_document->revision();
    Q_EMIT written(m_recoveryPath);
    return true;
}

void Autosaver::discard()
{
    QFile::remove(m_recoveryPath);
    QFile::remove(infoPath());
    m_writtenRevision = m_document->revision();
}

QString Autosaver::defaultDirectory()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
        .filePath(QStringLiteral("recovery"));
}

QList<RecoveryFile> Autosaver::leftovers(const QString &directory)
{
    QList<RecoveryFile> result;
    const QDir dir(directory);
    // An editor that crashed before its first autosave left only its lock (and perhaps the
    // info beside it): nothing to restore, so they go once their owner is gone, instead of
    // piling up crash after crash.
    const QStringList locks = dir.entryList({kRecoveryPrefix + QLatin1Char('*') + kLockSuffix}, QDir::Files);
    for (const QString &name : locks) {
        QString stem = dir.filePath(name);
        stem.chop(kLockSuffix.size());
        if (QFileInfo::exists(stem + kProjectSuffix))
            continue;
        QLockFile lock(stem + kLockSuffix);
        lock.setStaleLockTime(0);
        if (!lock.tryLock(0))
            continue; // a running editor's
        lock.unlock(); // removes the lock file
        QFile::remove(stem + kInfoSuffix);
    }
    const QStringList names = dir.entryList({kRecoveryPrefix + QLatin1Char('*') + kProjectSuffix}, QDir::Files);
    for (const QString &name : names) {
        const QString path = dir.filePath(name);
        const QString stem = stemOf(path);
        QLockFile lock(stem + kLockSuffix);
        lock.setStaleLockTime(0);
        if (!lock.tryLock(0))
            continue; // a running editor's file
        lock.unlock();

        RecoveryFile file;
        file.path = path;
        file.written = QFileInfo(path).lastModified();
        QFile infoFile(stem + kInfoSuffix);
        if (infoFile.open(QIODevice::ReadOnly)) {
            const QJsonObject info = QJsonDocument::fromJson(infoFile.readAll()).object();
            file.originalPath = info.value(QStringLiteral("originalPath")).toString();
        }
        result.append(file);
    }
    std::sort(result.begin(), result.end(),
        [](const RecoveryFile &a, const RecoveryFile &b) { return a.written > b.written; });
    return result;
}

LoadedFile Autosaver::load(const RecoveryFile &file)
{
    LoadedFile loaded = loadFile(file.path);
    loaded.path = file.originalPath;
    return loaded;
}

void Autosaver::restoreInto(Document *document, const LoadedFile &loaded)
{
    Q_ASSERT(loaded.ok());
    document->reset(loaded.project, loaded.photo, loaded.path, true);
    document->markModified();
}

void Autosaver::remove(const RecoveryFile &file)
{
    const QString stem = stemOf(file.path);
    QFile::remove(file.path);
    QFile::remove(stem + kInfoSuffix);
}

void Autosaver::onTimeout()
{
    autosave();
}

QString Autosaver::infoPath() const
{
    return stemOf(m_recoveryPath) + kInfoSuffix;
}

} // namespace toonface
