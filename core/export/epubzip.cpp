#include "export/epubzip.h"

#include "i18n/coretext.h"

#include <QtEndian>

#include <zlib.h>

#include <limits>

namespace toonface {

namespace {

constexpr quint32 kLocalSignature = 0x04034b50;
constexpr quint32 kCentralSignature = 0x02014b50;
constexpr quint32 kEndSignature = 0x06054b50;
constexpr quint16 kVersion = 20; // 2.0: deflate
constexpr quint16 kUtf8Names = 0x0800;
constexpr qint64 kZipLimit = std::numeric_limits<quint32>::max();

void put16(QByteArray &out, quint16 v)
{
    char b[2];
    qToLittleEndian(v, b);
    out.append(b, 2);
}

void put32(QByteArray &out, quint32 v)
{
    char b[4];
    qToLittleEndian(v, b);
    out.append(b, 4);
}

quint16 get16(const QByteArray &in, qsizetype at)
{
    return qFromLittleEndian<quint16>(in.constData() + at);
}

quint32 get32(const QByteArray &in, qsizetype at)
{
    return qFromLittleEndian<quint32>(in.constData() + at);
}

quint32 crcOf(const QByteArray &data, quint32 crc = 0)
{
    return quint32(crc32_z(crc, reinterpret_cast<const Bytef *>(data.constData()), size_t(data.size())));
}

} // namespace

QByteArray rawDeflate(const QByteArray &data)
{
    z_stream z {};
    if (deflateInit2(&z, 6, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        return {};
    QByteArray out(qsizetype(deflateBound(&z, uLong(data.size()))), Qt::Uninitialized);
    z.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(data.constData()));
    z.avail_in = uInt(data.size());
    z.next_out = reinterpret_cast<Bytef *>(out.data());
    z.avail_out = uInt(out.size());
    const int r = deflate(&z, Z_FINISH);
    out.resize(qsizetype(z.total_out));
    deflateEnd(&z);
    return r == Z_STREAM_END ? out : QByteArray();
}

QByteArray rawInflate(const QByteArray &data, qsizetype size)
{
    z_stream z {};
    if (inflateInit2(&z, -15) != Z_OK)
        return {};
    QByteArray out(size, Qt::Uninitialized);
    z.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(data.constData()));
    z.avail_in = uInt(data.size());
    z.next_out = reinterpret_cast<Bytef *>(out.data());
    z.avail_out = uInt(out.size());
    const int r = inflate(&z, Z_FINISH);
    const bool whole = r == Z_STREAM_END && qsizetype(z.total_out) == size;
    inflateEnd(&z);
    return whole ? out : QByteArray();
}

EpubZip::EpubZip(const QString &path, const QDateTime &modified)
    : m_file(path)
{
    // MS-DOS time: two-second steps from 1980.
    const QDateTime t = modified.toUTC();
    const int year = std::clamp(t.date().year(), 1980, 2107);
    m_dosDate = quint16(((year - 1980) << 9) | (t.date().month() << 5) | t.date().day());
    m_dosTime = quint16((t.time().hour() << 11) | (t.time().minute() << 5) | (t.time().second() / 2));
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        m_error = QStringLiteral("%1: %2").arg(path, ExportText::tr("cannot write: %1").arg(m_file.errorString()));
}

bool EpubZip::fail(const QString &problem)
{
    if (m_error.isEmpty())
        m_error = QStringLiteral("%1: %2").arg(m_file.fileName(), problem);
    m_file.close();
    return false;
}

bool EpubZip::write(const QByteArray &bytes)
{
    if (m_file.write(bytes) != bytes.size())
        return fail(ExportText::tr("cannot write: %1").arg(m_file.errorString()));
    m_offset += bytes.size();
    return true;
}

bool EpubZip::writeLocalHeader(Entry &entry, qint64 compressedSize, qint64 size)
{
    if (!isOpen())
        return false;
    if (size > kZipLimit || compressedSize > kZipLimit || m_offset > kZipLimit || m_entries.size() >= 0xffff)
        return fail(ExportText::tr("the book is too large for a ZIP archive (4 GiB, 65535 files)"));
    entry.compressedSize = quint32(compressedSize);
    entry.size = quint32(size);
    entry.offset = quint32(m_offset);
    QByteArray h;
    put32(h, kLocalSignature);
    put16(h, kVersion);
    put16(h, kUtf8Names);
    put16(h, entry.method);
    put16(h, m_dosTime);
    put16(h, m_dosDate);
    put32(h, entry.crc);
    put32(h, entry.compressedSize);
    put32(h, entry.size);
    put16(h, quint16(entry.name.size()));
    put16(h, 0);
    h += entry.name;
    return write(h);
}

bool EpubZip::add(const QString &name, const QByteArray &data, bool compress)
{
    Entry entry;
    entry.name = name.toUtf8();
    entry.crc = crcOf(data);
    QByteArray stored = data;
    if (compress) {
        stored = rawDeflate(data);
        if (stored.isEmpty() && !data.isEmpty())
            return fail(ExportText::tr("cannot compress %1").arg(name));
        entry.method = 8;
    }
    if (!writeLocalHeader(entry, stored.size(), data.size()) || !write(stored))
        return false;
    m_entries.push_back(entry);
    return true;
}

bool EpubZip::addFile(const QString &name, const QString &path)
{
    QFile in(path);
    if (!in.open(QIODevice::ReadOnly))
        return fail(ExportText::tr("cannot read %1: %2").arg(path, in.errorString()));
    constexpr qint64 kBlock = 1 << 20;
    // The CRC goes in the header before the data: one pass to compute it, one to copy.
    quint32 crc = 0;
    while (!in.atEnd()) {
        const QByteArray block = in.read(kBlock);
        if (block.isEmpty())
            return fail(ExportText::tr("cannot read %1: %2").arg(path, in.errorString()));
        crc = crcOf(block, crc);
    }
    Entry entry;
    entry.name = name.toUtf8();
    entry.crc = crc;
    if (!writeLocalHeader(entry, in.size(), in.size()) || !in.seek(0))
        return false;
    while (!in.atEnd()) {
        if (!write(in.read(kBlock)))
            return false;
    }
    m_entries.push_back(entry);
    return true;
}

bool EpubZip::finish()
{
    if (!isOpen())
        return false;
    const qint64 start = m_offset;
    QByteArray d;
    for (const Entry &e : m_entries) {
        put32(d, kCentralSignature);
        put16(d, kVersion); // made by: MS-DOS attributes, version 2.0
        put16(d, kVersion);
        put16(d, kUtf8Names);
        put16(d, e.method);
        put16(d, m_dosTime);
        put16(d, m_dosDate);
        put32(d, e.crc);
        put32(d, e.compressedSize);
        put32(d, e.size);
        put16(d, quint16(e.name.size()));
        put16(d, 0); // extra
        put16(d, 0); // comment
        put16(d, 0); // disk
        put16(d, 0); // internal attributes
        put32(d, 0); // external attributes
        put32(d, e.offset);
        d += e.name;
    }
    const qsizetype directorySize = d.size();
    if (start + directorySize > kZipLimit)
        return fail(ExportText::tr("the book is too large for a ZIP archive (4 GiB, 65535 files)"));
    put32(d, kEndSignature);
    put16(d, 0);
    put16(d, 0);
    put16(d, quint16(m_entries.size()));
    put16(d, quint16(m_entries.size()));
    put32(d, quint32(directorySize));
    put32(d, quint32(start));
    put16(d, 0);
    if (!write(d))
        return false;
    if (!m_file.flush())
        return fail(ExportText::tr("cannot write: %1").arg(m_file.errorString()));
    m_file.close();
    return true;
}

std::vector<ZipEntry> readZip(const QByteArray &archive, QString *error)
{
    auto bad = [error](const QString &problem) {
        if (error)
            *error = problem;
        return std::vector<ZipEntry>();
    };
    const qsizetype end = archive.lastIndexOf(QByteArray::fromRawData("PK\x05\x06", 4));
    if (end < 0 || end + 22 > archive.size())
        return bad(QStringLiteral("no end of central directory"));
    const int count = get16(archive, end + 10);
    qsizetype at = get32(archive, end + 16);
    std::vector<ZipEntry> entries;
    for (int i = 0; i < count; ++i) {
        if (at + 46 > archive.size() || get32(archive, at) != kCentralSignature)
            return bad(QStringLiteral("broken central directory"));
        ZipEntry e;
        e.method = get16(archive, at + 10);
        const quint32 crc = get32(archive, at + 16);
        const qsizetype packed = get32(archive, at + 20);
        const qsizetype size = get32(archive, at + 24);
        const int nameLength = get16(archive, at + 28);
        const int skip = nameLength + get16(archive, at + 30) + get16(archive, at + 32);
        const qsizetype local = get32(archive, at + 42);
        e.name = QString::fromUtf8(archive.mid(at + 46, nameLength));
        at += 46 + skip;
        if (local + 30 > archive.size() || get32(archive, local) != kLocalSignature)
            return bad(QStringLiteral("%1: broken local header").arg(e.name));
        const qsizetype data = local + 30 + get16(archive, local + 26) + get16(archive, local + 28);
        if (data + packed > archive.size())
            return bad(QStringLiteral("%1: truncated").arg(e.name));
        const QByteArray raw = archive.mid(data, packed);
        e.data = e.method == 8 ? rawInflate(raw, size) : raw;
        if (e.data.size() != size || crcOf(e.data) != crc)
            return bad(QStringLiteral("%1: bad data or CRC").arg(e.name));
        entries.push_back(std::move(e));
    }
    return entries;
}

} // namespace toonface
