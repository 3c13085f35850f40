#include "speech/pinyindictionary.h"
#include "speech/pinyinindex.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

using namespace toonface;

namespace {

PinyinSyllable syl(const char *pinyin, int tone)
{
    return {QString::fromUtf8(pinyin), tone};
}

bool writeFile(const QString &path, const QByteArray &data)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(data) == data.size();
}

// A small folder laid out like /usr/share: 1200 characters from U+4E00 read "yi1" … plus a few
// real ones, one traditional → simplified variant, and a phrase dictionary.
struct FakeRoot
{
    QTemporaryDir dir;
    QString root() const { return dir.path(); }
    QByteArray readings;
    QByteArray terra;

    FakeRoot()
    {
        static const char *cycle[] = {"yī", "èr", "sān", "sì", "wǔ"};
        for (int k = 0; k < 1200; ++k)
            readings += QStringLiteral("U+%1\tkMandarin\t%2\n")
                            .arg(QString::number(0x4E00 + k, 16).toUpper(), QString::fromUtf8(cycle[k % 5]))
                            .toUtf8();
        readings += "U+884C\tkMandarin\txíng\nU+884C\tkHanyuPinlu\txíng(2943) háng(218)\n";
        readings += "U+94F6\tkMandarin\tyín\nU+9280\tkMandarin\tyín\nU+957F\tkMandarin\tcháng\n";
        readings += "U+957F\tkHanyuPinlu\tcháng(1000) zhǎng(800)\n";
        terra = "---\nname: terra_pinyin\n...\n\n銀行\tyin2 hang2\n";
        write();
        writeFile(root() + QStringLiteral("/unicode/Unihan_Variants.txt"),
            "U+9280\tkSimplifiedVariant\tU+94F6\nU+9577\tkSimplifiedVariant\tU+957F\n");
    }
    void write()
    {
        writeFile(root() + QStringLiteral("/unicode/Unihan_Readings.txt"), readings);
        writeFile(root() + QStringLiteral("/rime-data/terra_pinyin.dict.yaml"), terra);
    }
};

QString spelled(const QVector<PinyinSyllable> &reading)
{
    QStringList out;
    for (const PinyinSyllable &s : reading)
        out.append(s.pinyin + QString::number(s.tone));
    return out.join(QLatin1Char(' '));
}

QString read(const PinyinDictionary &d, const char *utf8)
{
    return spelled(d.readRun(QString::fromUtf8(utf8).toStdU32String()));
}

} // namespace

class TestPinyinDictionary : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void indexRoundTrip()
    {
        QHash<char32_t, QVector<PinyinSyllable>> readings;
        readings.insert(U'行', {syl("xing", 2), syl("hang", 2)});
        readings.insert(U'长', {syl("chang", 2), syl("zhang", 3)});
        readings.insert(U'绿', {syl("lü", 4)});
        QHash<QString, QVector<PinyinSyllable>> phrases;
        phrases.insert(QStringLiteral("行长"), {syl("hang", 2), syl("zhang", 3)});
        phrases.insert(QStringLiteral("行长们"), {syl("hang", 2), syl("zhang", 3), syl("men", 5)});
        phrases.insert(QStringLiteral("长"), {syl("chang", 2)}); // one character: not a phrase length > 1, still kept
        QString error;
        const auto index = PinyinIndex::fromBlock(PinyinIndex::build(readings, phrases, 42), &error);
        QVERIFY2(index, qPrintable(error));
        QCOMPARE(index->sourceSignature(), quint64(42));
        QCOMPARE(index->characterCount(), 3);
        QCOMPARE(index->phraseCount(), 3);
        QCOMPARE(index->maxPhraseLength(), 3);
        QCOMPARE(spelled(index->readings(U'行')), QStringLiteral("xing2 hang2"));
        QCOMPARE(spelled(index->readings(U'绿')), QStringLiteral("lü4"));
        QVERIFY(index->readings(U'我').isEmpty());
        QVERIFY(!index->contains(U'我'));
        const std::u32string run = U"银行长们";
        QVERIFY(!index->phrase(run, 0, 2));
        QCOMPARE(spelled(*index->phrase(run, 1, 2)), QStringLiteral("hang2 zhang3"));
        QCOMPARE(spelled(*index->phrase(run, 1, 3)), QStringLiteral("hang2 zhang3 men5"));
        QVERIFY(!index->phrase(run, 1, 4)); // past the end
        QVERIFY(!index->phrase(run, 2, 2));
    }

    void damagedBlocksAreRefused()
    {
        QHash<char32_t, QVector<PinyinSyllable>> readings;
        readings.insert(U'行', {syl("xing", 2), syl("hang", 2)});
        QHash<QString, QVector<PinyinSyllable>> phrases;
        phrases.insert(QStringLiteral("行行"), {syl("hang", 2), syl("hang", 2)});
        const QByteArray good = PinyinIndex::build(readings, phrases, 1);
        QString error;
        QVERIFY(PinyinIndex::fromBlock(good, &error));
        for (qsizetype at = 0; at < good.size(); ++at) {
            QByteArray bad = good;
            bad[at] = char(bad[at] ^ 0x5a);
            // Any byte changed, header or body: refused.
            QVERIFY2(!PinyinIndex::fromBlock(bad, &error), qPrintable(QStringLiteral("byte %1").arg(at)));
        }
        QVERIFY(!PinyinIndex::fromBlock(good.left(good.size() - 4), &error));
        QVERIFY(error.contains(QLatin1String("bytes")));
        QVERIFY(!PinyinIndex::fromBlock(QByteArray(), &error));
        QVERIFY(!PinyinIndex::fromBlock(QByteArray(4096, 'x'), &error));
        QVERIFY(error.contains(QLatin1String("not a pinyin index")));
    }

    void builtOnceThenReused()
    {
        FakeRoot fake;
        QTemporaryDir cache;
        QString error, note;
        PinyinDictionary::CacheUse use {};
        auto d = PinyinDictionary::loadCached(fake.root(), cache.path(), &error, &use, &note);
        QVERIFY2(d, qPrintable(error));
        QCOMPARE(use, PinyinDictionary::CacheUse::Built);
        QVERIFY(QFile::exists(cache.filePath(QStringLiteral("pinyin-index.bin"))));
        QCOMPARE(read(*d, "银行"), QStringLiteral("yin2 hang2")); // the traditional phrase, simplified
        QCOMPARE(read(*d, "行"), QStringLiteral("xing2"));
        QCOMPARE(spelled(d->readings(U'行')), QStringLiteral("xing2 hang2"));
        const QDateTime written = QFileInfo(cache.filePath(QStringLiteral("pinyin-index.bin"))).lastModified();

        d = PinyinDictionary::loadCached(fake.root(), cache.path(), &error, &use, &note);
        QVERIFY2(d, qPrintable(error));
        QCOMPARE(use, PinyinDictionary::CacheUse::Reused);
        QCOMPARE(read(*d, "银行"), QStringLiteral("yin2 hang2"));
        QCOMPARE(QFileInfo(cache.filePath(QStringLiteral("pinyin-index.bin"))).lastModified(), written);
        // With a source gone the cache is stale, and the rebuild names what is missing.
        QVERIFY(QFile::remove(fake.root() + QStringLiteral("/unicode/Unihan_Readings.txt")));
        QVERIFY(!PinyinDictionary::loadCached(fake.root(), cache.path(), &error, &use, &note));
        QVERIFY2(error.contains(QLatin1String("unicode-data")), qPrintable(error));
    }

    void rebuiltWhenTheSourcesChange()
    {
        FakeRoot fake;
        QTemporaryDir cache;
        QString error;
        PinyinDictionary::CacheUse use {};
        auto d = PinyinDictionary::loadCached(fake.root(), cache.path(), &error, &use);
        QVERIFY2(d, qPrintable(error));
        QCOMPARE(read(*d, "银行长"), QStringLiteral("yin2 hang2 chang2"));
        // A phrase added to the phrase dictionary.
        fake.terra += "行長\thang2 zhang3\n";
        fake.write();
        d = PinyinDictionary::loadCached(fake.root(), cache.path(), &error, &use);
        QVERIFY2(d, qPrintable(error));
        QCOMPARE(use, PinyinDictionary::CacheUse::RebuiltStale);
        QCOMPARE(read(*d, "行长"), QStringLiteral("hang2 zhang3"));
        d = PinyinDictionary::loadCached(fake.root(), cache.path(), &error, &use);
        QCOMPARE(use, PinyinDictionary::CacheUse::Reused);
        QCOMPARE(read(*d, "行长"), QStringLiteral("hang2 zhang3"));
        // A character's reading changed (same size, later time).
        fake.readings.replace("U+94F6\tkMandarin\tyín", "U+94F6\tkMandarin\tyǐn");
        QTest::qWait(20);
        fake.write();
        d = PinyinDictionary::loadCached(fake.root(), cache.path(), &error, &use);
        QVERIFY2(d, qPrintable(error));
        QCOMPARE(use, PinyinDictionary::CacheUse::RebuiltStale);
        QCOMPARE(spelled(d->readings(U'银')), QStringLiteral("yin3"));
    }

    void damagedCacheIsIgnoredAndRebuilt_data()
    {
        QTest::addColumn<int>("damage");
        QTest::newRow("a byte flipped in the middle") << 0;
        QTest::newRow("truncated") << 1;
        QTest::newRow("empty") << 2;
        QTest::newRow("another file") << 3;
        QTest::newRow("a folder in its place") << 4;
    }
    void damagedCacheIsIgnoredAndRebuilt()
    {
        QFETCH(int, damage);
        FakeRoot fake;
        QTemporaryDir cache;
        const QString path = cache.filePath(QStringLiteral("pinyin-index.bin"));
        QString error, note;
        PinyinDictionary::CacheUse use {};
        QVERIFY(PinyinDictionary::loadCached(fake.root(), cache.path(), &error, &use));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QByteArray bytes = f.readAll();
        f.close();
        switch (damage) {
        case 0: bytes[bytes.size() / 2] = char(bytes[bytes.size() / 2] ^ 1); break;
        case 1: bytes.chop(bytes.size() / 3); break;
        case 2: bytes.clear(); break;
        case 3: bytes = "not an index at all, just some text that happens to be here\n"; break;
        }
        if (damage == 4) {
            QVERIFY(QFile::remove(path));
            QVERIFY(QDir().mkpath(path + QStringLiteral("/inside")));
        } else {
            QVERIFY(writeFile(path, bytes));
        }
        auto d = PinyinDictionary::loadCached(fake.root(), cache.path(), &error, &use, &note);
        QVERIFY2(d, qPrintable(error));
        QCOMPARE(read(*d, "银行"), QStringLiteral("yin2 hang2"));
        QCOMPARE(spelled(d->readings(U'行')), QStringLiteral("xing2 hang2"));
        if (damage == 4) {
            // Cannot be replaced: the dictionary still works, the note says why.
            QCOMPARE(use, PinyinDictionary::CacheUse::NotWritten);
            QVERIFY2(note.contains(path), qPrintable(note));
            return;
        }
        QCOMPARE(use, PinyinDictionary::CacheUse::RebuiltDamaged);
        QVERIFY2(note.contains(path), qPrintable(note));
        d = PinyinDictionary::loadCached(fake.root(), cache.path(), &error, &use);
        QCOMPARE(use, PinyinDictionary::CacheUse::Reused);
        QCOMPARE(read(*d, "银行"), QStringLiteral("yin2 hang2"));
    }

    // The cached index reads the installed dictionaries exactly as parsing them does.
    void cachedReadsLikeTheSources()
    {
        QString root = qEnvironmentVariable("TOONFACE_DICT_ROOT");
        if (root.isEmpty())
            root = QStringLiteral("/usr/share");
        QTemporaryDir cache;
        QString error;
        PinyinDictionary::CacheUse use {};
        const auto parsed = PinyinDictionary::load(root, &error);
        QVERIFY2(parsed, qPrintable(error));
        QVERIFY(PinyinDictionary::loadCached(root, cache.path(), &error, &use));
        QCOMPARE(use, PinyinDictionary::CacheUse::Built);
        const auto cached = PinyinDictionary::loadCached(root, cache.path(), &error, &use);
        QVERIFY2(cached, qPrintable(error));
        QCOMPARE(use, PinyinDictionary::CacheUse::Reused);
        QCOMPARE(cached->phraseCount(), parsed->phraseCount());
        QVERIFY(cached->phraseCount() > 10000);
        for (const char *text : {"银行行长说这绝对不行", "经广州日报报道后成为了社会热点", "我爱北京天安门",
                 "你更喜欢老鹰还是鹦鹉", "而对楼市成交抑制作用最大的限购", "也成为地方政府的眼中钉", "銀行"}) {
            QCOMPARE(read(*cached, text), read(*parsed, text));
        }
        for (char32_t c = 0x4E00; c < 0x9FA5; c += 7)
            QCOMPARE(cached->readings(c), parsed->readings(c));
    }

    // The process-wide dictionary lives in TOONFACE_CACHE_DIR when that is set.
    void sharedUsesTheCacheDirectoryFromTheEnvironment()
    {
        QTemporaryDir cache;
        qputenv("TOONFACE_CACHE_DIR", cache.path().toUtf8());
        QCOMPARE(PinyinDictionary::cacheDirectory(), cache.path());
        QString error;
        const auto d = PinyinDictionary::shared(&error);
        QVERIFY2(d, qPrintable(error));
        QVERIFY(QFile::exists(cache.filePath(QStringLiteral("pinyin-index.bin"))));
        QCOMPARE(read(*d, "你好"), QStringLiteral("ni3 hao3"));
        qunsetenv("TOONFACE_CACHE_DIR");
        QVERIFY(PinyinDictionary::cacheDirectory().endsWith(QLatin1String("/toonface")));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestPinyinDictionary)
#include "tst_pinyindictionary.moc"
