#include "export/partfiles.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

#include <cerrno>
#include <csignal>

namespace toonface {

namespace {

bool processIsGone(qint64 pid)
{
    return pid > 0 && ::kill(pid_t(pid), 0) == -1 && errno == ESRCH;
}

} // namespace

void removeStaleParts(const QString &target)
{
    const QFileInfo info(QDir::cleanPath(target));
    const QDir dir = info.absoluteDir();
    const QString stem = QLatin1Char('.') + info.fileName() + QLatin1Char('.');
    const QRegularExpression part(QStringLiteral("^%1(\\d+)-\\d+\\.part$").arg(QRegularExpression::escape(stem)));
    const QStringList names = dir.entryList({stem + QStringLiteral("*.part")},
        QDir::Files | QDir::Dirs | QDir::Hidden | QDir::NoDotAndDotDot | QDir::NoSymLinks);
    for (const QString &name : names) {
        const QRegularExpressionMatch m = part.match(name);
        if (!m.hasMatch() || !processIsGone(m.captured(1).toLongLong()))
            continue;
        const QString path = dir.filePath(name);
        if (QFileInfo(path).isDir())
            QDir(path).removeRecursively();
        else
            QFile::remove(path);
    }
}

} // namespace toonface
