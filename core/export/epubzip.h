#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QFile>
#include <QString>

#include <vector>

namespace toonface {

// A ZIP archive written front to back, as EPUB's container (OCF) wants it: entries in the
// order they are added (the book's `mimetype` first, stored), each either stored or deflated
// (zlib's raw deflate), UTF-8 names, no extra fields, no data descriptors. Entries and the
// archive stay below ZIP's 32-bit limits (4 GiB, 65535 entries): a larger book is an error,
// never a ZIP64 archive that some reading systems cannot open.
class EpubZip
{
public:
    // Writes to `path`, which it creates (or empties). All entries get the time `modified`.
    EpubZip(const QString &path, const QDateTime &modified);

    bool isOpen() const { return m_error.isEmpty(); }
    // What went wrong, naming the archive's file.
    QString errorString() const { return m_error; }

    // Adds `data` as the entry `name`, deflated when `compress` (stored otherwise).
    bool add(const QString &name, const QByteArray &data, bool compress);
    // Adds the file `path`, stored (already compressed media), copied in blocks.
    bool addFile(const QString &name, const QString &path);
    // Writes the central directory and closes the file.
    bool finish();

    qint64 size() const { return m_offset; }

private:
    struct Entry
    {
        QByteArray name;
        quint32 crc = 0;
        quint32 compressedSize = 0;
        quint32 size = 0;
        quint32 offset = 0;
        quint16 method = 0;
    };

    bool fail(const QString &problem);
    bool writeLocalHeader(Entry &entry, qint64 compressedSize, qint64 size);
    bool write(const QByteArray &bytes);

    QFile m_file;
    QString m_error;
    std::vector<Entry> m_entries;
    qint64 m_offset = 0;
    quint16 m_dosTime = 0;
    quint16 m_dosDate = 0;
};

// zlib's raw deflate of `data` (no zlib header: ZIP's method 8).
QByteArray rawDeflate(const QByteArray &data);
// The inverse, for readers of the archive (tests): empty when `data` is not raw deflate.
QByteArray rawInflate(const QByteArray &data, qsizetype size);

// The entries of a ZIP archive (as EpubZip writes them) by name, in order, with their
// decompressed content, for reading a book back. Empty with *error when it is not one.
struct ZipEntry
{
    QString name;
    quint16 method = 0;
    QByteArray data;
};
std::vector<ZipEntry> readZip(const QByteArray &archive, QString *error);

} // namespace toonface
