#include "benchmark.h"

#include "anim/timeline.h"
#include "face/averageface.h"
#include "face/mouthshape.h"
#include "io/project.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <sys/stat.h>

using namespace toonface;

namespace {

// A project from a stranger, exported by its receiver: each hostile case as toonface-cli
// animate runs it, with its exit code (3 = refused by name), wall time and peak memory. The
// issue's targets are a clean export or a clear error in under 5 s and 500 MB.
struct HostileCase
{
    const char *name;
    QString sound; // the project's sound path, or empty
    QStringList layerFiles;
    QByteArray inlineLayer; // an inline layer written into the JSON by hand, or empty
    QString suffix = QStringLiteral("html");
};

bool writeFile(const QString &path, const QByteArray &content)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(content) == content.size();
}

QString writeProject(const QString &dir, const HostileCase &c)
{
    Project p;
    p.face = averageFace(QRectF(106, 130, 300, 330), QSize(512, 512));
    QVector<MouthKey> keys;
    for (int i = 0; i < 40; ++i)
        keys.append(MouthKey {i * 0.1, kAllMouthShapes[size_t(i) % kAllMouthShapes.size()], 1.0, std::nullopt});
    p.timeline.setMouthKeys(keys);
    if (!c.sound.isEmpty())
        p.timeline.setAudioClips({AudioClip {QDir(dir).absoluteFilePath(c.sound), 0.0, 4.0}});
    p.layerPaths = c.layerFiles;
    const QString path = QDir(dir).filePath(
        QString::fromLatin1(c.name).replace(QLatin1Char(' '), QLatin1Char('-')) + QStringLiteral(".toonface"));
    QString error;
    if (!saveProject(p, path, &error))
        return {};
    if (c.inlineLayer.isEmpty())
        return path;
    // Written as an attacker would, past the cleaning reader.
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    file.close();
    QJsonObject style = json.value(QStringLiteral("style")).toObject();
    style.insert(QStringLiteral("layers"),
        QJsonArray {QJsonObject {{QStringLiteral("name"), QStringLiteral("hostile.svg")},
            {QStringLiteral("svg"), QString::fromUtf8(c.inlineLayer)}, {QStringLiteral("x"), 0},
            {QStringLiteral("y"), 0}, {QStringLiteral("width"), 2}, {QStringLiteral("front"), true},
            {QStringLiteral("visible"), true}}});
    json.insert(QStringLiteral("style"), style);
    return writeFile(path, QJsonDocument(json).toJson()) ? path : QString();
}

QJsonObject benchHostileProjects()
{
    QTemporaryDir home;
    const QString shared = home.filePath(QStringLiteral("shared"));
    QDir().mkpath(shared);
    writeFile(home.filePath(QStringLiteral("id_rsa")), "-----BEGIN OPENSSH PRIVATE KEY-----\nAAAA\n");
    const QString fifo = home.filePath(QStringLiteral("pipe"));
    ::mkfifo(QFile::encodeName(fifo).constData(), 0600);

    QByteArray deep = "<svg xmlns=\"http://www.w3.org/2000/svg\">";
    for (int i = 0; i < 100000; ++i)
        deep += "<g>";
    for (int i = 0; i < 100000; ++i)
        deep += "</g>";
    deep += "</svg>";
    writeFile(shared + QStringLiteral("/deep.svg"), deep);
    writeFile(shared + QStringLiteral("/svg11.svg"),
        "<?xml version=\"1.0\"?>\n<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" "
        "\"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd\">\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
        "viewBox=\"0 0 10 10\"><text>a&nbsp;b</text><rect width=\"4\" height=\"4\"/></svg>");
    QByteArray many = "<svg xmlns=\"http://www.w3.org/2000/svg\">";
    for (int i = 0; i < 200000; ++i)
        many += "<rect width=\"1\" height=\"1\"/>";
    many += "</svg>";
    writeFile(shared + QStringLiteral("/many.svg"), many);
    const QByteArray at = "http://127.0.0.1:9";
    const QByteArray hostile = "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:h=\"http://www.w3.org/1999/xhtml\">"
                               "<style>@\\69mport '"
        + at + "/a.css'; rect{fill:\\75 rl(" + at + "/b)}</style><p/><img srcset=\"" + at
        + "/d.png 1x\"/><h:meta http-equiv=\"refresh\" content=\"0;url=" + at + "/i\"/></svg>";

    const QList<HostileCase> cases = {
        {"private key as sound", QStringLiteral("../id_rsa"), {}, {}},
        {"private key as sound mp4", QStringLiteral("../id_rsa"), {}, {}, QStringLiteral("mp4")},
        {"dev zero as sound", QStringLiteral("/dev/zero"), {}, {}},
        {"fifo as sound", fifo, {}, {}},
        {"folder as sound", home.path(), {}, {}},
        {"dev zero as layer", {}, {QStringLiteral("/dev/zero")}, {}},
        {"fifo as layer", {}, {fifo}, {}},
        {"100000 nested groups", {}, {shared + QStringLiteral("/deep.svg")}, {}, QStringLiteral("svg")},
        {"200000 elements", {}, {shared + QStringLiteral("/many.svg")}, {}, QStringLiteral("svg")},
        {"SVG 1.1 doctype with nbsp", {}, {shared + QStringLiteral("/svg11.svg")}, {}, QStringLiteral("svg")},
        {"CSS escapes and XHTML in a layer", {}, {}, hostile},
        {"CSS escapes and XHTML in a layer svg", {}, {}, hostile, QStringLiteral("svg")},
    };
    QJsonArray rows;
    double worstMs = 0, worstMb = 0;
    bool allClear = true;
    for (const HostileCase &c : cases) {
        const QString project = writeProject(shared, c);
        const QString out = home.filePath(QStringLiteral("out.") + c.suffix);
        QFile::remove(out);
        const bench::ChildRun run = bench::runMeasured(QStringLiteral(TOONFACE_CLI_PATH),
            {QStringLiteral("animate"), project, QStringLiteral("-o"), out},
            {QStringLiteral("QT_QPA_PLATFORM=offscreen")}, true);
        // Clear: a clean export (0) or an error naming a file (3); nothing else.
        const bool clear = run.exitCode == 0 || (run.exitCode == 3 && run.stderrText.contains("error: "));
        allClear = allClear && clear;
        worstMs = std::max(worstMs, run.wallMs);
        worstMb = std::max(worstMb, run.peakMb);
        QByteArray firstError = run.stderrText;
        firstError = firstError.mid(std::max(qsizetype(0), firstError.indexOf("error: ")));
        firstError.truncate(firstError.indexOf('\n') < 0 ? firstError.size() : firstError.indexOf('\n'));
        rows.append(QJsonObject {{QStringLiteral("case"), QString::fromLatin1(c.name)},
            {QStringLiteral("exitCode"), run.exitCode}, {QStringLiteral("wallMs"), qRound(run.wallMs)},
            {QStringLiteral("peakMb"), qRound(run.peakMb)},
            {QStringLiteral("message"), QString::fromUtf8(firstError)}});
    }
    return {{QStringLiteral("cases"), rows}, {QStringLiteral("worstWallMs"), qRound(worstMs)},
        {QStringLiteral("worstPeakMb"), qRound(worstMb)}, {QStringLiteral("targetWallMs"), 5000},
        {QStringLiteral("targetPeakMb"), 500}, {QStringLiteral("everyCaseCleanOrNamed"), allClear}};
}

} // namespace

TOONFACE_BENCHMARK("security.hostileProjects", benchHostileProjects);
