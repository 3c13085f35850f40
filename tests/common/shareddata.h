#pragma once

#include <QDir>
#include <QFile>
#include <QHash>
#include <QList>
#include <QString>
#include <QStringList>
#include <QTextStream>

namespace toonface::testing {

// The shared research data (photos, speech, video): TOONFACE_DATA_DIR, else the build's
// default (../shared/data). Tests that read it skip when what they need is absent.
inline QString sharedDataDir()
{
    const QString env = qEnvironmentVariable("TOONFACE_DATA_DIR");
    return env.isEmpty() ? QStringLiteral(TOONFACE_SHARED_DATA) : env;
}

// Its folder of research photos.
inline QString sharedFacesDir()
{
    return QDir(sharedDataDir()).filePath(QStringLiteral("faces"));
}

// One face of the labelled set (faces-attributes/labels.tsv): its columns by name and its photo.
struct LabelledFace
{
    QHash<QString, QString> columns;
    QString photoPath;
    QString operator[](const char *column) const { return columns.value(QString::fromLatin1(column)); }
    bool flag(const char *column) const { return (*this)[column] == QLatin1String("1"); }
};

// The labelled faces in the file's order; none when the set is absent (the caller skips).
inline QList<LabelledFace> labelledFaces()
{
    const QDir dir(QDir(sharedDataDir()).filePath(QStringLiteral("faces-attributes")));
    QFile tsv(dir.filePath(QStringLiteral("labels.tsv")));
    QList<LabelledFace> faces;
    if (!tsv.open(QIODevice::ReadOnly | QIODevice::Text))
        return faces;
    QTextStream in(&tsv);
    const QStringList header = in.readLine().split(QLatin1Char('\t'));
    while (!in.atEnd()) {
        const QStringList cells = in.readLine().split(QLatin1Char('\t'));
        if (cells.size() < header.size())
            continue;
        LabelledFace face;
        for (qsizetype i = 0; i < header.size(); ++i)
            face.columns.insert(header[i], cells[i]);
        face.photoPath = dir.filePath(face["file"]);
        faces.append(face);
    }
    return faces;
}

inline constexpr const char *kNoLabelledFaces = "the labelled faces are not here (../shared/data/faces-attributes)";

} // namespace toonface::testing
