#include "export/videosink.h"

#include "i18n/coretext.h"
#include "media/pngframes.h"

#include <QDir>
#include <QFileInfo>
#include <QImageWriter>
#include <QSaveFile>

namespace toonface::av {

namespace {

class PngSink : public Sink
{
public:
    ~PngSink() override { cancel(); }

    bool open(const QString &folder, QSize size, QString *error)
    {
        if (size.width() < 1 || size.height() < 1 || size.width() > 32768 || size.height() > 32768)
            return fail(error, folder,
                ExportText::tr("unsupported size %1x%2 (PNG frames take 1 to 32768 pixels a side)")
                    .arg(size.width())
                    .arg(size.height()));
        const QFileInfo info(folder);
        if (info.exists() && !info.isDir())
            return fail(error, folder, ExportText::tr("cannot write PNG frames: it is a file, not a folder"));
        if (!QDir().mkpath(folder))
            return fail(error, folder, ExportText::tr("cannot create the folder for PNG frames"));
        m_dir = QDir(folder);
        m_folder = folder;
        return true;
    }

    bool addFrame(const QImage &frame, QString *error) override
    {
        const QString path = m_dir.filePath(pngFrameName(m_count + 1));
        QSaveFile file(path);
        if (!file.open(QIODevice::WriteOnly))
            return fail(error, m_folder,
                ExportText::tr("cannot write %1: %2").arg(pngFrameName(m_count + 1), file.errorString()));
        QImageWriter writer(&file, "png");
        if (!writer.write(frame)) {
            file.cancelWriting();
            return fail(error, m_folder,
                ExportText::tr("cannot write %1: %2").arg(pngFrameName(m_count + 1), writer.errorString()));
        }
        if (!file.commit())
            return fail(error, m_folder,
                ExportText::tr("cannot write %1: %2").arg(pngFrameName(m_count + 1), file.errorString()));
        ++m_count;
        return true;
    }

    bool finish(QString *) override
    {
        const QStringList names = m_dir.entryList({QStringLiteral("frame_*.png")}, QDir::Files);
        for (const QString &name : names) {
            const QRegularExpressionMatch m = pngFramePattern().match(name);
            if (m.hasMatch() && m.captured(1).toLongLong() > m_count)
                m_dir.remove(name);
        }
        m_count = -1; // done: nothing to cancel
        return true;
    }

    void cancel() override
    {
        for (int i = 1; i <= m_count; ++i)
            m_dir.remove(pngFrameName(i));
        m_count = 0;
    }

private:
    QDir m_dir;
    QString m_folder;
    int m_count = 0;
};

} // namespace

std::unique_ptr<Sink> openPngSink(const QString &folder, QSize size, QString *error)
{
    auto sink = std::make_unique<PngSink>();
    if (!sink->open(folder, size, error))
        return nullptr;
    return sink;
}

} // namespace toonface::av
