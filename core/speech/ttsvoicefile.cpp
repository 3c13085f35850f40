#include "speech/ttsvoicefile.h"

#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QSaveFile>

namespace toonface {

namespace {

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QString findBaseVoice(const QString &name, const QString &dataDir)
{
    QDirIterator it(dataDir + QStringLiteral("/lang"), QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        it.next();
        if (it.fileName().compare(name, Qt::CaseInsensitive) == 0)
            return it.filePath();
    }
    return {};
}

} // namespace

QString steadyVoiceFile(const QString &voice, const QString &dataDir, const QString &dir)
{
    const QString base = voice.section(QLatin1Char('+'), 0, 0);
    const QString variant = voice.section(QLatin1Char('+'), 1);
    if (base.isEmpty() || base.contains(QLatin1Char('/')) || variant.contains(QLatin1Char('/')))
        return {};
    // A short name: espeak-ng reads at most 59 characters of a voice file's path.
    const QString path = dir + QStringLiteral("/v%1").arg(quint32(qHash(voice)), 8, 16, QLatin1Char('0'));
    if (QFileInfo::exists(path))
        return path;
    const QString basePath = findBaseVoice(base, dataDir);
    if (basePath.isEmpty())
        return {};
    QByteArray text = readAll(basePath);
    if (text.isEmpty())
        return {};
    if (!text.endsWith('\n'))
        text += '\n';
    if (!variant.isEmpty()) {
        const QByteArray v = readAll(dataDir + QStringLiteral("/voices/!v/") + variant);
        if (v.isEmpty())
            return {};
        // The variant's attributes only: its name and "language variant" would rename the
        // voice or add a language to it.
        for (const QByteArray &line : v.split('\n')) {
            const QByteArray t = line.trimmed();
            if (t.startsWith("name") || t.startsWith("language"))
                continue;
            text += line + '\n';
        }
    }
    text += "flutter 0\n";
    QSaveFile out(path);
    if (!out.open(QIODevice::WriteOnly) || out.write(text) != text.size() || !out.commit())
        return {};
    return path;
}

} // namespace toonface
