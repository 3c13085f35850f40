#include "benchmark.h"

#include "detect/appearance.h"
#include "detect/detector.h"
#include "detect/photocolours.h"
#include "face/emotion.h"
#include "face/pose.h"
#include "render/style.h"
#include "render/svgface.h"

#include <QDir>
#include <QJsonArray>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <optional>
#include <random>

// likeness.sheet: every shared face and the Debian portraits, as a user would cartoon them
// (detect, sample the style, draw), with what the appearance detection found per face. Writes a
// contact sheet (photo with the points | cartoon) as a PNG to TOONFACE_SHEET (default
// likeness-sheet.png in the working directory) for a person to look at: it is not data to commit.
// (TOONFACE_SHEET_FACES=attributes: 40 labelled faces instead, see attributeSubjects.)

using namespace toonface;

namespace {

struct Subject
{
    QString name;
    QString path;
    std::optional<QPointF> faceAt;
};

// TOONFACE_SHEET_FACES=attributes: 40 faces of faces-attributes (research data, looked at here,
// never committed), drawn at random with a fixed seed, instead of the shared photos.
std::vector<Subject> attributeSubjects(const QString &data)
{
    std::vector<Subject> out;
    const QDir images(QDir(data).filePath(QStringLiteral("faces-attributes/images")));
    QStringList files = images.entryList({QStringLiteral("*.jpg")}, QDir::Files, QDir::Name);
    std::mt19937 rng(25);
    std::shuffle(files.begin(), files.end(), rng);
    for (const QString &f : files.mid(0, 40))
        out.push_back({f.section(QLatin1Char('.'), 0, 0), images.filePath(f), std::nullopt});
    return out;
}

std::vector<Subject> subjects()
{
    std::vector<Subject> out;
    const QString data = bench::sharedDataDir();
    if (qEnvironmentVariable("TOONFACE_SHEET_FACES") == QLatin1String("attributes"))
        return data.isEmpty() ? out : attributeSubjects(data);
    if (!data.isEmpty()) {
        const QDir faces(QDir(data).filePath(QStringLiteral("faces")));
        for (const char *name : {"lfpw_trainset_image_0001.png", "lfpw_trainset_image_0002.png",
                 "lfpw_trainset_image_0003.png", "einstein.jpg"})
            out.push_back({QString::fromLatin1(name).section(QLatin1Char('.'), 0, 0),
                faces.filePath(QLatin1StringView(name)), std::nullopt});
        const QPointF bald[]
            = {{143, 132}, {390, 88}, {949, 143}, {1589, 220}, {861, 883}, {1147, 838}, {497, 861}, {1170, 1368}};
        for (int i = 0; i < 8; ++i)
            out.push_back(
                {QStringLiteral("bald_guys#%1").arg(i + 1), faces.filePath(QStringLiteral("bald_guys.jpg")), bald[i]});
        const QPointF men[] = {{155, 120}, {268, 145}, {388, 120}};
        for (int i = 0; i < 3; ++i)
            out.push_back({QStringLiteral("2008_002506#%1").arg(i + 1),
                faces.filePath(QStringLiteral("2008_002506.jpg")), men[i]});
    }
    out.push_back({QStringLiteral("grace_hopper"),
        QStringLiteral("/usr/share/matplotlib/mpl-data/sample_data/grace_hopper.jpg"), std::nullopt});
    out.push_back({QStringLiteral("astronaut"),
        QStringLiteral("/usr/lib/python3/dist-packages/skimage/data/astronaut.png"), std::nullopt});
    return out;
}

// The photo's part in `frame` with the face's points over it: hair outline, forehead, contour.
QImage photoPanel(const QImage &photo, const FaceModel &face, const QRectF &frame, int size)
{
    QImage panel(size, size, QImage::Format_RGB32);
    panel.fill(Qt::white);
    QPainter p(&panel);
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    const double s = size / std::max(frame.width(), frame.height());
    p.scale(s, s);
    p.translate(-frame.topLeft());
    p.drawImage(QPointF(0, 0), photo);
    p.setPen(QPen(QColor(255, 230, 0), 1.5 / s));
    QPolygonF hair;
    for (int i = 0; i < 19; ++i)
        hair << face.point(pt::idx("h.1") + i);
    p.drawPolyline(hair);
    p.setPen(QPen(QColor(0, 230, 255), 1.5 / s));
    p.drawPolyline(QPolygonF {face.point("11.2"), face.point("11.1"), face.point("11.3")});
    return panel;
}

// Saves a sheet to TOONFACE_SHEET (else `fallback` in the working directory); the result lists
// the faces and where the sheet went.
QJsonObject sheetResult(const QImage &sheet, const QJsonArray &faces, const QString &fallback)
{
    const QString path = qEnvironmentVariable("TOONFACE_SHEET", fallback);
    QJsonObject result;
    result.insert(QStringLiteral("faces"), faces);
    result.insert(QStringLiteral("sheet"), sheet.save(path) ? path : QStringLiteral("not written: ") + path);
    return result;
}

QJsonObject sheet()
{
    const int cell = 260;
    std::vector<std::pair<QImage, QImage>> rows;
    std::vector<QString> labels;
    QJsonArray people;
    for (const Subject &s : subjects()) {
        const QImage photo(s.path);
        QJsonObject o;
        o.insert(QStringLiteral("name"), s.name);
        if (photo.isNull()) {
            o.insert(QStringLiteral("error"), QStringLiteral("not found"));
            people.append(o);
            continue;
        }
        DetectOptions options;
        options.faceAt = s.faceAt;
        const DetectionResult r = detectFace(photo, options);
        if (r.status != DetectStatus::Ok) {
            o.insert(QStringLiteral("error"), r.error);
            people.append(o);
            continue;
        }
        Style style = Style::preset(QStringLiteral("normal"));
        AppearanceFindings f;
        sampleColours(photo, r.face, &style, &f);
        const Appearance &a = style.appearance;
        o.insert(QStringLiteral("glasses"), glassesShapeName(a.glasses));
        o.insert(QStringLiteral("moustache"), a.moustache);
        o.insert(QStringLiteral("beard"), a.beard);
        o.insert(QStringLiteral("goatee"), a.goatee);
        o.insert(QStringLiteral("hat"), a.hat);
        o.insert(QStringLiteral("bald"), a.bald);
        o.insert(QStringLiteral("hair"), style.components.value(QStringLiteral("hair")).fill.name());
        o.insert(QStringLiteral("skin"), style.components.value(QStringLiteral("face")).fill.name());
        o.insert(QStringLiteral("brows"), style.components.value(QStringLiteral("eyebrows")).fill.name());
        QJsonObject scores;
        scores.insert(QStringLiteral("glasses"), f.glassesScore);
        scores.insert(QStringLiteral("mTex"), f.moustacheTexture);
        scores.insert(QStringLiteral("mSpeckle"), f.moustacheSpeckle);
        scores.insert(QStringLiteral("cheekSpeckle"), f.cheekSpeckle);
        scores.insert(QStringLiteral("bTex"), f.beardTexture);
        scores.insert(QStringLiteral("skinReach"), f.skinReach);
        scores.insert(QStringLiteral("temples"), f.templeHair.isValid() ? f.templeHair.name() : QString());
        scores.insert(QStringLiteral("c2h"), f.crownToHair);
        scores.insert(QStringLiteral("c2s"), f.crownToSkin);
        scores.insert(QStringLiteral("spread"), f.brimSpread);
        scores.insert(QStringLiteral("bridged"), f.bridgedDark);
        if (a.lens.isSet())
            scores.insert(
                QStringLiteral("lens"), QJsonArray {a.lens.halfWidth, a.lens.halfHeight, a.lens.outward, a.lens.down});
        scores.insert(QStringLiteral("moustache"), f.moustacheScore);
        scores.insert(QStringLiteral("beard"), f.beardScore);
        scores.insert(QStringLiteral("goatee"), f.goateeScore);
        scores.insert(QStringLiteral("jaw"), f.jawScore);
        scores.insert(QStringLiteral("facialHair"), f.facialHair.isValid() ? f.facialHair.name() : QString());
        scores.insert(QStringLiteral("bald"), f.baldScore);
        scores.insert(QStringLiteral("hat"), f.hatScore);
        const AppearanceEvidence &e = f.evidence;
        scores.insert(QStringLiteral("evidence"),
            QJsonArray {e.lipRedLoss, e.lipDL, e.chinRedLoss, e.chinDetail, e.chinDL, e.jawRedLoss, e.bridgeLine,
                e.lowerRims, e.sideRims});
        o.insert(QStringLiteral("scores"), scores);
        people.append(o);

        SvgFace cartoon(r.face, style);
        cartoon.setFrame(headFrame(r.face));
        const QImage drawn = rasterizeSvg(cartoon.svg(), QSize(cell, cell));
        rows.emplace_back(photoPanel(photo, r.face, cartoon.frame(), cell), drawn);
        QStringList seen;
        if (a.glasses != GlassesShape::None)
            seen << QStringLiteral("glasses");
        if (a.moustache)
            seen << QStringLiteral("moustache");
        if (a.beard)
            seen << QStringLiteral("beard");
        if (a.goatee)
            seen << QStringLiteral("goatee");
        if (a.hat)
            seen << QStringLiteral("hat");
        if (a.bald)
            seen << QStringLiteral("bald");
        labels.push_back(s.name + QLatin1Char(' ') + seen.join(QLatin1Char(',')));
    }
    const int columns = 4; // pairs per row
    const int label = 18;
    const int nrows = int((rows.size() + columns - 1) / columns);
    QImage out(columns * 2 * cell, std::max(1, nrows) * (cell + label), QImage::Format_RGB32);
    out.fill(Qt::white);
    QPainter p(&out);
    for (size_t i = 0; i < rows.size(); ++i) {
        const int x = int(i % columns) * 2 * cell, y = int(i / columns) * (cell + label);
        p.drawImage(x, y + label, rows[i].first);
        p.drawImage(x + cell, y + label, rows[i].second);
        p.setPen(Qt::black);
        p.drawText(QRect(x + 4, y, 2 * cell - 8, label), Qt::AlignVCenter, labels[i]);
    }
    p.end();
    return sheetResult(out, people, QStringLiteral("likeness-sheet.png"));
}

// likeness.emotions: each face's cartoon with the five emotions at full and at half intensity
// (two rows a face), as a PNG to TOONFACE_SHEET (default emotion-sheet.png), for a person to
// judge whether each reads; the JSON lists the faces drawn.
QJsonObject emotions()
{
    const int cell = 200, label = 16;
    const double intensities[] = {1.0, 0.5};
    std::vector<std::pair<QString, std::vector<QImage>>> rows;
    QJsonArray people;
    for (const Subject &s : subjects()) {
        const QImage photo(s.path);
        if (photo.isNull())
            continue;
        DetectOptions options;
        options.faceAt = s.faceAt;
        const DetectionResult r = detectFace(photo, options);
        if (r.status != DetectStatus::Ok)
            continue;
        Style style = Style::preset(QStringLiteral("normal"));
        sampleColours(photo, r.face, &style);
        SvgFace cartoon(r.face, style);
        cartoon.setFrame(headFrame(r.face));
        for (double intensity : intensities) {
            std::vector<QImage> cells;
            for (Emotion e : kAllEmotions)
                cells.push_back(rasterizeSvg(cartoon.svg(stillEmotionPose(r.face, e, intensity)), QSize(cell, cell)));
            rows.emplace_back(QStringLiteral("%1 at %2").arg(s.name).arg(intensity), std::move(cells));
        }
        people.append(s.name);
    }
    QImage out(
        int(kAllEmotions.size()) * cell, std::max<int>(1, int(rows.size())) * (cell + label), QImage::Format_RGB32);
    out.fill(Qt::white);
    QPainter p(&out);
    for (size_t i = 0; i < rows.size(); ++i) {
        const int y = int(i) * (cell + label);
        QStringList names;
        for (Emotion e : kAllEmotions)
            names << emotionName(e);
        p.setPen(Qt::black);
        p.drawText(QRect(4, y, out.width() - 8, label), Qt::AlignVCenter,
            rows[i].first + QStringLiteral(": ") + names.join(QStringLiteral(", ")));
        for (size_t k = 0; k < rows[i].second.size(); ++k)
            p.drawImage(int(k) * cell, y + label, rows[i].second[k]);
    }
    p.end();
    return sheetResult(out, people, QStringLiteral("emotion-sheet.png"));
}

} // namespace

TOONFACE_BENCHMARK("likeness.sheet", sheet);
TOONFACE_BENCHMARK("likeness.emotions", emotions);
