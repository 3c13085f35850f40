#include "detect/shapemodelfile.h"

#include "detect/landmarkflat.h"
#include "i18n/coretext.h"

#include <QFile>

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace toonface {

namespace {

using namespace flat;

// Why the decoding stopped: what follows the file's name in the message.
struct Malformed
{
    QString why;
};
struct OldFormat
{
};

// dlib's float_details: a value is mantissa x 2^exponent, except for these exponents.
constexpr int kInfinity = 32000, kMinusInfinity = 32001;

// A mapping of memory that ends with the object owning it (the file's, or the block's).
struct Mapping
{
    void *data = MAP_FAILED;
    size_t size = 0;
    Mapping() = default;
    Mapping(const Mapping &) = delete;
    Mapping &operator=(const Mapping &) = delete;
    ~Mapping()
    {
        if (data != MAP_FAILED)
            munmap(data, size);
    }
};

// Reads dlib's serialised numbers from the mapped file, front to back.
class Decoder
{
public:
    Decoder(const uchar *data, size_t size)
        : m_begin(data)
        , m_p(data)
        , m_end(data + size)
    { }

    size_t at() const { return size_t(m_p - m_begin); }

    // An unsigned integer (dlib's unsigned long).
    quint64 unsignedInt()
    {
        const int n = control(false);
        return bytes(n);
    }

    // A signed integer of `maxBytes` bytes at most (dlib's long: 8, int: 4, int16: 2).
    template<typename T>
    T signedInt()
    {
        const bool negative = need(1) && (*m_p & 0x80);
        const int n = control(true);
        if (n > int(sizeof(T)))
            malformed("a number too large for its type");
        // As dlib assembles it: the bytes in T's width, then negated.
        T value = T(bytes(n));
        if (negative)
            value = T(0 - std::make_unsigned_t<T>(value));
        return value;
    }

    // A float: its mantissa and its power of two, converted as dlib converts them
    // (std::ldexp(float(mantissa), exponent)); a product with an exact power of two where that
    // is the same number.
    float real()
    {
        if (!need(1))
            cutShort();
        // dlib's old format wrote floats as text: its first byte has bits the control byte of
        // the binary format never has.
        if (*m_p & 0x70)
            throw OldFormat {};
        const qint64 mantissa = signedInt<qint64>();
        const int exponent = signedInt<qint16>();
        if (exponent < kInfinity) {
            const float m = float(mantissa);
            if (exponent >= -126 && exponent <= 127)
                return m * std::bit_cast<float>(quint32(exponent + 127) << 23);
            return std::ldexp(m, exponent);
        }
        if (exponent == kInfinity)
            return std::numeric_limits<float>::infinity();
        if (exponent == kMinusInfinity)
            return -std::numeric_limits<float>::infinity();
        return std::numeric_limits<float>::quiet_NaN();
    }

    // A matrix's rows and columns (negated in dlib's current format).
    std::pair<qint64, qint64> matrixSize()
    {
        qint64 rows = signedInt<qint64>(), columns = signedInt<qint64>();
        if (rows == std::numeric_limits<qint64>::min() || columns == std::numeric_limits<qint64>::min())
            malformed("a matrix of impossible size");
        if (rows < 0 || columns < 0) {
            rows = -rows;
            columns = -columns;
        }
        return {rows, columns};
    }

    [[noreturn]] void malformed(const char *what) const
    {
        throw Malformed {DetectText::tr("could not be read: %1 at byte %2").arg(QLatin1StringView(what)).arg(at())};
    }
    [[noreturn]] void cutShort() const
    {
        throw Malformed {
            DetectText::tr("could not be read: it ends early (at byte %1, in the middle of the model)").arg(at())};
    }

private:
    bool need(size_t n) const { return size_t(m_end - m_p) >= n; }

    // The control byte: the count of bytes that follow.
    int control(bool isSigned)
    {
        if (!need(1))
            cutShort();
        const uchar c = *m_p;
        // dlib masks the bits it reserves: the sign's too for an unsigned number, whose count
        // then exceeds 8.
        const int n = isSigned ? (c & 0x0F) : (c & 0x8F);
        if (n == 0 || n > 8)
            malformed("a malformed number");
        ++m_p;
        return n;
    }

    // `n` bytes, least significant first.
    quint64 bytes(int n)
    {
        quint64 v = 0;
        if (need(8)) {
            std::memcpy(&v, m_p, 8);
            if (n < 8)
                v &= (quint64(1) << (8 * n)) - 1;
        } else {
            if (!need(size_t(n)))
                cutShort();
            for (int i = n - 1; i >= 0; --i)
                v = (v << 8) | m_p[i];
        }
        m_p += n;
        return v;
    }

    const uchar *m_begin;
    const uchar *m_p;
    const uchar *m_end;
};

// The block being filled: a reservation of address space at least as large as any block the
// file could make, whose pages become memory (zeroed, which the padding between sections
// must be) only as they are written.
class Block
{
public:
    explicit Block(size_t capacity)
        : m_mapping(std::make_shared<Mapping>())
    {
        m_mapping->size = capacity;
        m_mapping->data
            = mmap(nullptr, capacity, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
        if (m_mapping->data == MAP_FAILED)
            throw Malformed {DetectText::tr("could not be read: no memory for it (%1)")
                                 .arg(QString::fromLocal8Bit(std::strerror(errno)))};
    }

    // The offset of a section of `bytes` bytes, after the ones reserved before it.
    size_t reserve(size_t bytes, const Decoder &in)
    {
        const size_t at = alignUp(m_used);
        if (at > m_mapping->size || bytes > m_mapping->size - at)
            in.malformed("counts larger than the file could hold");
        m_used = at + bytes;
        return at;
    }

    template<typename T>
    T *at(size_t offset)
    {
        return reinterpret_cast<T *>(static_cast<std::byte *>(m_mapping->data) + offset);
    }

    // The block as laid out, the reservation beyond it given back.
    std::pair<std::shared_ptr<const void>, std::span<const std::byte>> finish()
    {
        const size_t size = m_used; // ends with its last array, as landmarkpredictor.cpp's blocks do
        const size_t page = size_t(sysconf(_SC_PAGESIZE));
        const size_t kept = (size + page - 1) / page * page;
        if (kept < m_mapping->size) {
            munmap(static_cast<std::byte *>(m_mapping->data) + kept, m_mapping->size - kept);
            m_mapping->size = kept;
        }
        return {m_mapping, std::span<const std::byte>(at<const std::byte>(0), size)};
    }

private:
    std::shared_ptr<Mapping> m_mapping;
    size_t m_used = 0;
};

// The largest block a file of `fileBytes` bytes could make: every number of the file takes
// at least two bytes (a control byte and one), a float four; the block gives a float, a
// threshold or an offset's coordinate four bytes, a split's pair of features four (two
// numbers of the file), an anchor four (one number: the one array that can grow, twofold),
// and each section up to 63 bytes of padding.
size_t blockCapacity(size_t fileBytes)
{
    return 2 * fileBytes + kSectionAlignment * (5 * kMaxCascades + 3) + sizeof(Header) + sizeof(Cascade) * kMaxCascades;
}

void decode(Decoder &in, Block &block)
{
    if (in.signedInt<int>() != 1)
        in.malformed("an unknown format version");
    const auto [rows, columns] = in.matrixSize();
    if (columns != 1 || rows != kShapeValues) {
        if (columns == 1 && rows >= 0 && rows % 2 == 0 && rows < 1000000)
            throw Malformed {DetectText::tr("gives %1 points, not the 68 of the iBUG scheme.").arg(rows / 2)};
        in.malformed("a mean shape that is not a column of points");
    }
    Header header {};
    std::copy(std::begin(kMagic), std::end(kMagic), header.magic);
    header.version = kVersion;
    header.points = kIbugPointCount;
    block.reserve(sizeof(Header), in);
    header.initialAt = block.reserve(kShapeValues * sizeof(float), in);
    float *initial = block.at<float>(header.initialAt);
    for (int i = 0; i < kShapeValues; ++i)
        initial[i] = in.real();

    const quint64 cascades = in.unsignedInt();
    if (cascades == 0 || cascades > kMaxCascades)
        in.malformed("an implausible number of cascades");
    header.cascades = quint32(cascades);
    header.tableAt = block.reserve(cascades * sizeof(Cascade), in);
    std::vector<Cascade> table(cascades);
    for (Cascade &c : table) {
        const quint64 trees = in.unsignedInt();
        if (trees == 0 || trees > kMaxTrees)
            in.malformed("an implausible number of trees");
        c.trees = quint32(trees);
        for (quint64 t = 0; t < trees; ++t) {
            const quint64 splits = in.unsignedInt();
            if (t == 0) {
                if (splits > kMaxSplitsPerTree)
                    in.malformed("an implausible depth of tree");
                // The first tree gives the depth of all: the cascade's arrays are placed now.
                c.splitsPerTree = quint32(splits);
                c.splitFeaturesAt = block.reserve(trees * splits * 2 * sizeof(quint16), in);
                c.thresholdsAt = block.reserve(trees * splits * sizeof(float), in);
                c.leavesAt = block.reserve(trees * (splits + 1) * kShapeValues * sizeof(float), in);
            } else if (splits != c.splitsPerTree) {
                in.malformed("trees of a cascade that differ in depth");
            }
            quint16 *features = block.at<quint16>(c.splitFeaturesAt) + 2 * t * splits;
            float *thresholds = block.at<float>(c.thresholdsAt) + t * splits;
            for (quint64 s = 0; s < splits; ++s) {
                const quint64 a = in.unsignedInt(), b = in.unsignedInt();
                if (a >= kMaxFeatures || b >= kMaxFeatures)
                    in.malformed("a split that reads a feature out of range");
                features[2 * s] = quint16(a);
                features[2 * s + 1] = quint16(b);
                thresholds[s] = in.real();
            }
            if (in.unsignedInt() != splits + 1)
                in.malformed("a tree whose leaves do not match its splits");
            float *leaf = block.at<float>(c.leavesAt) + t * (splits + 1) * kShapeValues;
            for (quint64 l = 0; l <= splits; ++l, leaf += kShapeValues) {
                if (in.matrixSize() != std::pair<qint64, qint64>(kShapeValues, 1))
                    in.malformed("a leaf that is not a 68-point shape");
                for (int v = 0; v < kShapeValues; ++v)
                    leaf[v] = in.real();
            }
        }
    }

    // The pixel features: every cascade's anchors, then every cascade's offsets.
    if (in.unsignedInt() != cascades)
        in.malformed("pixel features that do not match the cascades");
    for (Cascade &c : table) {
        const quint64 features = in.unsignedInt();
        if (features > kMaxFeatures)
            in.malformed("an implausible number of pixel features");
        c.features = quint32(features);
        c.anchorsAt = block.reserve(features * sizeof(quint32), in);
        quint32 *anchors = block.at<quint32>(c.anchorsAt);
        for (quint64 f = 0; f < features; ++f) {
            const quint64 anchor = in.unsignedInt();
            if (anchor >= quint64(kIbugPointCount))
                in.malformed("a pixel feature anchored to no point");
            anchors[f] = quint32(anchor);
        }
    }
    if (in.unsignedInt() != cascades)
        in.malformed("pixel features that do not match the cascades");
    for (Cascade &c : table) {
        if (in.unsignedInt() != c.features)
            in.malformed("pixel features that do not match their anchors");
        c.deltasAt = block.reserve(2 * quint64(c.features) * sizeof(float), in);
        float *deltas = block.at<float>(c.deltasAt);
        for (quint64 f = 0; f < 2 * quint64(c.features); ++f)
            deltas[f] = in.real();
    }
    std::memcpy(block.at<Header>(0), &header, sizeof header);
    std::memcpy(block.at<Cascade>(header.tableAt), table.data(), table.size() * sizeof(Cascade));
}

} // namespace

ShapeModelFile readShapeModelFile(const QString &path)
{
    ShapeModelFile out;
    const int fd = open(QFile::encodeName(path).constData(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        out.error = DetectText::tr("could not be opened: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
        return out;
    }
    struct stat info
    {
    };
    Mapping file;
    if (fstat(fd, &info) == 0 && info.st_size > 0) {
        file.size = size_t(info.st_size);
        // Populated at once: the file is read whole, front to back.
        file.data = mmap(nullptr, file.size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    }
    close(fd);
    if (file.data == MAP_FAILED && info.st_size > 0) {
        out.error = DetectText::tr("could not be read: %1").arg(QString::fromLocal8Bit(std::strerror(errno)));
        return out;
    }
    Decoder in(static_cast<const uchar *>(file.data == MAP_FAILED ? nullptr : file.data), file.size);
    try {
        if (file.size == 0)
            in.cutShort();
        Block block(blockCapacity(file.size));
        decode(in, block);
        std::tie(out.owner, out.block) = block.finish();
        out.status = ShapeModelFile::Status::Read;
    } catch (const Malformed &m) {
        out.error = m.why;
    } catch (const OldFormat &) {
        out.status = ShapeModelFile::Status::OldFormat;
    }
    return out;
}

} // namespace toonface
