#include "io/imageio.h"

#include "i18n/coretext.h"
#include "media/userfile.h"

#include <QBuffer>
#include <QColorSpace>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImageReader>

#include <cstring>

namespace toonface {

namespace {

// A compressed photo larger than this is far beyond the pixel budget anyway.
constexpr qint64 kMaxPhotoFileBytes = 1024ll * 1024 * 1024;

QString withFile(const QString &path, const QString &message)
{
    return withProblem(QDir::toNativeSeparators(path), message);
}

bool startsWith(const QByteArray &data, qsizetype at, const char *magic)
{
    return data.size() >= at + qsizetype(std::strlen(magic))
        && std::memcmp(data.constData() + at, magic, std::strlen(magic)) == 0;
}

bool looksLikeText(const QByteArray &head)
{
    const QString decoded = QString::fromUtf8(head);
    if (decoded.contains(QChar::ReplacementCharacter)) {
        // The sample may end inside a multi-byte character: allow a cut at the very end only.
        if (decoded.indexOf(QChar::ReplacementCharacter) < decoded.size() - 3)
            return false;
    }
    for (QChar c : decoded) {
        if (c.unicode() < 0x20 && c != u'\n' && c != u'\r' && c != u'\t')
            return false;
    }
    return true;
}

// What a file that no image reader accepts looks like, for the error message.
QString describeNonImage(const QByteArray &data)
{
    const QByteArray head = data.left(512);
    if (startsWith(head, 0, "RIFF") && startsWith(head, 8, "WEBP"))
        return ImageText::tr("a WebP image, which this build cannot read; convert it to PNG or JPEG");
    if (startsWith(head, 4, "ftypheic") || startsWith(head, 4, "ftypheix") || startsWith(head, 4, "ftypmif1")
        || startsWith(head, 4, "ftyphevc"))
        return ImageText::tr("a HEIC image, which this build cannot read; convert it to PNG or JPEG");
    if (startsWith(head, 4, "ftypavif"))
        return ImageText::tr("an AVIF image, which this build cannot read; convert it to PNG or JPEG");
    if (startsWith(head, 0, "II*") || startsWith(head, 0, "MM"))
        if (head.size() >= 4 && (head.at(2) == '*' || head.at(3) == '*'))
            return ImageText::tr("a TIFF image, which this build cannot read; convert it to PNG or JPEG");
    if (startsWith(head, 4, "ftyp"))
        return ImageText::tr("a video or audio file (MP4/QuickTime), not a photo");
    if (startsWith(head, 0, "RIFF") && startsWith(head, 8, "WAVE"))
        return ImageText::tr("a WAV audio file, not a photo");
    if (startsWith(head, 0, "ID3") || startsWith(head, 0, "OggS") || startsWith(head, 0, "fLaC"))
        return ImageText::tr("an audio file, not a photo");
    if (startsWith(head, 0, "%PDF"))
        return ImageText::tr("a PDF document, not an image");
    if (startsWith(head, 0, "PK\x03\x04"))
        return ImageText::tr("a ZIP archive (or an office document), not an image");
    if (looksLikeText(head)) {
        QString sample = QString::fromUtf8(head.left(40)).simplified();
        return ImageText::tr("text, not an image (it starts with \"%1\")").arg(sample);
    }
    QStringList bytes;
    for (qsizetype i = 0; i < qMin<qsizetype>(8, head.size()); ++i)
        bytes << QStringLiteral("%1").arg(uchar(head.at(i)), 2, 16, QLatin1Char('0'));
    return ImageText::tr("not an image (unrecognised data starting with %1)").arg(bytes.join(QLatin1Char(' ')));
}

// The first PNG chunk (before IEND) whose declared length runs past the end of the file,
// described, or empty. libpng trusts a chunk's length when it allocates room for it: a file
// of a few hundred bytes whose text chunk claims 2 GB makes it take that much memory.
QString pngOverrun(const QByteArray &data)
{
    static const QByteArray signature("\x89PNG\r\n\x1a\n", 8);
    if (!data.startsWith(signature))
        return {};
    qint64 at = signature.size();
    while (at + 8 <= data.size()) {
        const auto *p = reinterpret_cast<const uchar *>(data.constData() + at);
        const quint32 length = (quint32(p[0]) << 24) | (quint32(p[1]) << 16) | (quint32(p[2]) << 8) | p[3];
        const QByteArray type = data.mid(at + 4, 4);
        const qint64 left = data.size() - (at + 8);
        if (type == "IEND")
            return {};
        if (qint64(length) + 4 > left) // the data and its CRC
            return ImageText::tr("its %1 chunk claims %2 bytes, but only %3 are left in the file")
                .arg(QString::fromLatin1(type.toPercentEncoding()))
                .arg(length)
                .arg(std::max<qint64>(0, left - 4));
        at += 12 + qint64(length);
    }
    return {};
}

enum class JpegEnd { Complete, Truncated, Unknown };

// Walks the JPEG's marker segments and entropy-coded scans to its end-of-image marker.
// libjpeg decodes a truncated file "successfully", padding it with grey, so this is how a
// cut-off download is told from a photo. Data after the end marker (multi-picture previews,
// motion-photo videos) is ignored.
JpegEnd jpegEnd(const QByteArray &data)
{
    const auto *p = reinterpret_cast<const uchar *>(data.constData());
    const qsizetype n = data.size();
    if (n < 2 || p[0] != 0xFF || p[1] != 0xD8)
        return JpegEnd::Unknown;
    qsizetype pos = 2;
    while (true) {
        if (pos >= n)
            return JpegEnd::Truncated;
        if (p[pos] != 0xFF)
            return JpegEnd::Unknown; // not a marker where one must be: let the decoder judge
        while (pos < n && p[pos] == 0xFF)
            ++pos;
        if (pos >= n)
            return JpegEnd::Truncated;
        const uchar marker = p[pos++];
        if (marker == 0xD9)
            return JpegEnd::Complete;
        if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7))
            continue; // no length field
        if (pos + 2 > n)
            return JpegEnd::Truncated;
        const qsizetype length = (qsizetype(p[pos]) << 8) | p[pos + 1];
        if (length < 2)
            return JpegEnd::Unknown;
        pos += length;
        if (pos > n)
            return JpegEnd::Truncated;
        if (marker != 0xDA)
            continue;
        // Entropy-coded data: 0xFF is followed by 0x00 (a stuffed byte), a restart marker, or
        // fill bytes; any other marker ends the scan.
        while (true) {
            const void *ff = std::memchr(p + pos, 0xFF, size_t(n - pos));
            if (!ff)
                return JpegEnd::Truncated;
            pos = static_cast<const uchar *>(ff) - p;
            qsizetype next = pos + 1;
            while (next < n && p[next] == 0xFF)
                ++next;
            if (next >= n)
                return JpegEnd::Truncated;
            if (p[next] == 0x00 || (p[next] >= 0xD0 && p[next] <= 0xD7)) {
                pos = next + 1;
                continue;
            }
            pos = next - 1;
            break;
        }
    }
}

// RGB32 in sRGB; transparency composited on white.
QImage toRgb32(const QImage &image)
{
    QImage out;
    if (image.hasAlphaChannel()) {
        const QImage premultiplied = image.convertToFormat(QImage::Format_ARGB32_Premultiplied);
        out = QImage(image.size(), QImage::Format_RGB32);
        for (int y = 0; y < out.height(); ++y) {
            const auto *src = reinterpret_cast<const QRgb *>(premultiplied.constScanLine(y));
            auto *dst = reinterpret_cast<QRgb *>(out.scanLine(y));
            for (int x = 0; x < out.width(); ++x) {
                const int white = 255 - qAlpha(src[x]);
                dst[x] = qRgb(qRed(src[x]) + white, qGreen(src[x]) + white, qBlue(src[x]) + white);
            }
        }
        out.setColorSpace(image.colorSpace());
        out.setDotsPerMeterX(image.dotsPerMeterX());
        out.setDotsPerMeterY(image.dotsPerMeterY());
    } else {
        out = image.convertToFormat(QImage::Format_RGB32);
    }
    const QColorSpace srgb(QColorSpace::SRgb);
    if (out.colorSpace().isValid() && out.colorSpace() != srgb)
        out.convertToColorSpace(srgb);
    return out;
}

} // namespace

QImage loadPhoto(const QString &path, QString *error)
{
    QString scratch;
    if (!error)
        error = &scratch;
    const QFileInfo info(path);
    if (!info.exists()) {
        *error = withFile(path, ImageText::tr("no such file"));
        return {};
    }
    if (info.isDir()) {
        *error = withFile(path, ImageText::tr("is a folder, not an image"));
        return {};
    }
    if (const QString problem = irregularFileProblem(path); !problem.isEmpty()) {
        *error = withFile(path, problem); // a device or a pipe: never opened
        return {};
    }
    if (info.size() == 0) {
        *error = withFile(path, ImageText::tr("the file is empty"));
        return {};
    }
    if (info.size() > kMaxPhotoFileBytes) {
        *error = withFile(path, ImageText::tr("the file is too large for a photo (%1 MB)").arg(info.size() >> 20));
        return {};
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = withFile(path, ImageText::tr("cannot read: %1").arg(file.errorString()));
        return {};
    }
    QByteArray data = file.readAll();
    file.close();

    QBuffer buffer(&data);
    buffer.open(QIODevice::ReadOnly);
    // Without a file name the reader recognises the format from the content, so a PNG named
    // .jpg still loads and a text file named .jpg is reported for what it is.
    QImageReader reader(&buffer);
    reader.setAutoTransform(true);
    // Room for the largest allowed image at 8 bytes a pixel (16-bit RGBA): decoding beyond
    // that fails cleanly instead of exhausting memory when a header lies about its size.
    reader.setAllocationLimit(int((kMaxPhotoPixels * 8 + (1 << 20) - 1) >> 20));
    if (!reader.canRead()) {
        *error = withFile(path, describeNonImage(data));
        return {};
    }
    if (jpegEnd(data) == JpegEnd::Truncated) {
        *error
            = withFile(path, ImageText::tr("the JPEG image is truncated (the file ends before the image data does)"));
        return {};
    }
    const QString format = QString::fromLatin1(reader.format()).toUpper();
    if (const QString overrun = pngOverrun(data); !overrun.isEmpty()) {
        *error = withFile(path, ImageText::tr("the PNG image is corrupt or truncated (%1)").arg(overrun));
        return {};
    }
    const QSize size = reader.size();
    if (size.isValid()) {
        const qint64 pixels = qint64(size.width()) * size.height();
        if (pixels == 0) {
            *error = withFile(path,
                ImageText::tr("the %1 image is empty (%2 × %3 pixels)")
                    .arg(format)
                    .arg(size.width())
                    .arg(size.height()));
            return {};
        }
        if (pixels > kMaxPhotoPixels) {
            *error = withFile(path,
                ImageText::tr("the image is too large: %1 × %2 pixels (%3 megapixels); "
                              "the limit is %4 megapixels")
                    .arg(size.width())
                    .arg(size.height())
                    .arg(double(pixels) / 1e6, 0, 'f', 0)
                    .arg(kMaxPhotoPixels / 1000000));
            return {};
        }
    }
    const QImage image = reader.read();
    if (image.isNull()) {
        *error = withFile(
            path, ImageText::tr("the %1 image is corrupt or truncated (%2)").arg(format, reader.errorString()));
        return {};
    }
    return toRgb32(image);
}

} // namespace toonface
