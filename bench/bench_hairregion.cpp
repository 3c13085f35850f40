#include "benchmark.h"
#include "crossvalidation.h"
#include "facecache.h"

#include "detect/appearance.h"
#include "detect/headparse.h"
#include "face/pointtable.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QPainter>
#include <QPainterPath>
#include <QTextStream>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cstring>
#include <ctime>
#include <map>

// likeness.hairregion: how well the hair the cartoon draws covers the person's hair, over
// faces-attributes (research-only: measured, never shipped). The drawn hair region is the inside
// of the hair outline (h.1 … h.19, closed under the jaw at 2.13, 2.14) less the face (its
// contour through the hairline 11.x), as the cartoon shows it. It is scored by IoU
// - against the labelled hair of the faces that have a label map (masks/, CelebAMask-HQ), and
// - against the parse's hair (headparse.h: the person's pixels that are not skin, above the
//   brows all of them, beside the face those of the crown's hair colour), on the faces whose
//   parse saw the crown's hair and the whole head (no headwear labelled), and apart on the tight
//   crops that cut the crown off, within the photo (the hair beside the face).
// TOONFACE_FACE_CACHE=DIR reads the faces from there (a cache filled by another build of the
// detector measures that build's outlines: before and after a change, on the same photos).

using namespace toonface;

namespace {

QPolygonF polygon(const FaceModel &face, const std::vector<const char *> &ids, const QTransform &t)
{
    QPolygonF p;
    for (const char *id : ids)
        p << t.map(face.point(id));
    return p;
}

// The drawn hair region in a frame `t` maps the photo to, `size` pixels: 255 where hair is drawn.
cv::Mat drawnHair(const FaceModel &face, const QTransform &t, QSize size)
{
    QPolygonF outline;
    for (int k = 0; k < 19; ++k)
        outline << t.map(face.point(pt::idx("h.1") + k));
    outline << t.map(face.point("2.13")) << t.map(face.point("2.14"));
    QPainterPath hair, skin;
    hair.addPolygon(outline);
    hair.closeSubpath();
    skin.addPolygon(polygon(face, {"11.2", "11.1", "11.3", "5.1", "2.13", "2.11", "2.1", "2.12", "2.14", "5.2"}, t));
    skin.closeSubpath();
    QImage mask(size, QImage::Format_Grayscale8);
    mask.fill(0);
    QPainter p(&mask);
    p.setPen(Qt::NoPen);
    p.setBrush(Qt::white);
    p.drawPath(hair.subtracted(skin));
    p.end();
    cv::Mat out(size.height(), size.width(), CV_8UC1);
    for (int y = 0; y < size.height(); ++y)
        std::memcpy(out.ptr(y), mask.constScanLine(y), size_t(size.width()));
    return out;
}

double iou(const cv::Mat &a, const cv::Mat &b, const cv::Mat &within)
{
    const cv::Mat both = (a > 0) & (b > 0) & within, either = ((a > 0) | (b > 0)) & within;
    const int n = cv::countNonZero(either);
    return n > 0 ? double(cv::countNonZero(both)) / n : 0.0;
}

// The parse's hair in its work frame: 255 where the person is not skin above the brows' top, or
// of the crown's hair colour (within 18 L*a*b* units, the parse's own distance) beside the face
// below it; the face itself (contour and brows) left out.
cv::Mat parsedHair(const HeadParse &parse, const FaceModel &face)
{
    const int w = parse.size.width(), h = parse.size.height();
    const QImage rgb = parse.work.convertToFormat(QImage::Format_RGB888);
    cv::Mat src(rgb.height(), rgb.width(), CV_8UC3, const_cast<uchar *>(rgb.constBits()), size_t(rgb.bytesPerLine()));
    cv::Mat lab, hairLab;
    cv::cvtColor(src, lab, cv::COLOR_RGB2Lab);
    cv::Mat hairPixel(1, 1, CV_8UC3, cv::Scalar(parse.hair.red(), parse.hair.green(), parse.hair.blue()));
    cv::cvtColor(hairPixel, hairLab, cv::COLOR_RGB2Lab);
    const cv::Vec3b hc = hairLab.at<cv::Vec3b>(0, 0);
    cv::Mat out(h, w, CV_8UC1, cv::Scalar(0));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (parse.at(x, y) != HeadParse::Other)
                continue;
            const cv::Vec3b c = lab.at<cv::Vec3b>(y, x);
            const double dist = std::hypot((c[0] - hc[0]) * 100.0 / 255.0, double(c[1] - hc[1]), double(c[2] - hc[2]));
            if (y < parse.browTop || dist < 18.0)
                out.at<std::uint8_t>(y, x) = 255;
        }
    std::vector<cv::Point> skin;
    for (const char *id : {"11.2", "11.1", "11.3", "5.1", "2.13", "2.11", "2.1", "2.12", "2.14", "5.2"}) {
        const QPointF q = parse.toWork.map(face.point(id));
        skin.emplace_back(int(std::lround(q.x())), int(std::lround(q.y())));
    }
    cv::fillPoly(out, std::vector<std::vector<cv::Point>> {skin}, cv::Scalar(0));
    return out;
}

QJsonObject hairRegion()
{
    const QString data = bench::sharedDataDir();
    const QString dir = data.isEmpty() ? QString() : QDir(data).filePath(QStringLiteral("faces-attributes"));
    QFile tsv(QDir(dir).filePath(QStringLiteral("labels.tsv")));
    if (dir.isEmpty() || !tsv.open(QIODevice::ReadOnly | QIODevice::Text))
        return {{QStringLiteral("error"),
            QStringLiteral("faces-attributes/labels.tsv not found under the shared data folder")}};
    QTextStream in(&tsv);
    const QStringList header = in.readLine().split(QLatin1Char('\t'));
    const int fileCol = int(header.indexOf(QStringLiteral("file"))),
              hatCol = int(header.indexOf(QStringLiteral("headwear")));
    const int lengthCol = int(header.indexOf(QStringLiteral("hair_length")));
    std::clock_t cpu = 0;
    QStringList report;
    std::vector<double> parsedIou, cropIou;
    std::map<QString, std::vector<double>> byLength, cropByLength;
    QJsonArray labelled;
    int faces = 0;
    while (!in.atEnd()) {
        const QStringList c = in.readLine().split(QLatin1Char('\t'));
        if (c.size() < header.size())
            continue;
        const QString file = c[fileCol];
        const QImage photo(QDir(dir).filePath(file));
        if (photo.isNull())
            return {{QStringLiteral("error"), QStringLiteral("%1: not readable").arg(file)}};
        const std::optional<FaceModel> face = bench::detectCached(photo, QFileInfo(file).completeBaseName());
        if (!face)
            continue;
        ++faces;
        const std::clock_t start = std::clock();
        // Against the label map (CelebAMask-HQ: 13 is hair, at half the photo's size).
        const QString maskPath
            = QDir(dir).filePath(QStringLiteral("masks/%1.label.png").arg(QFileInfo(file).completeBaseName()));
        if (QFile::exists(maskPath)) {
            const QImage labels = QImage(maskPath).convertToFormat(QImage::Format_Grayscale8);
            const QTransform toMask = QTransform::fromScale(
                double(labels.width()) / photo.width(), double(labels.height()) / photo.height());
            const cv::Mat drawn = drawnHair(*face, toMask, labels.size());
            cv::Mat hair(labels.height(), labels.width(), CV_8UC1, cv::Scalar(0));
            for (int y = 0; y < labels.height(); ++y)
                for (int x = 0; x < labels.width(); ++x)
                    hair.at<std::uint8_t>(y, x) = labels.constScanLine(y)[x] == 13 ? 255 : 0;
            const cv::Mat all(hair.size(), CV_8UC1, cv::Scalar(255));
            const double v = iou(drawn, hair, all);
            labelled.append(QJsonObject {{QStringLiteral("file"), file}, {QStringLiteral("iou"), v}});
            report << QStringLiteral("%1: IoU with the labelled hair %2").arg(file).arg(v, 0, 'f', 3);
        }
        // Against the parse's hair, where it saw the crown's hair and the whole head; and, apart,
        // on the tight crops that cut the crown off (the hair beside the face, in the colour the
        // temples gave, below the photo's top edge: what the crop shows).
        const HeadParse parse = parseHead(photo, *face);
        const bool whole = parse.hairSeen && !parse.crownCut && !parse.topCut;
        const bool crop = parse.crownCut && parse.templeHairSeen && !parse.roomFall;
        if (parse.valid && (whole || crop) && c[hatCol] != QLatin1String("1")) {
            cv::Mat inside(parse.size.height(), parse.size.width(), CV_8UC1);
            for (int y = 0; y < inside.rows; ++y)
                for (int x = 0; x < inside.cols; ++x)
                    inside.at<std::uint8_t>(y, x) = parse.at(x, y) == HeadParse::Outside ? 0 : 255;
            const double v = iou(drawnHair(*face, parse.toWork, parse.size), parsedHair(parse, *face), inside);
            (whole ? parsedIou : cropIou).push_back(v);
            if (whole)
                byLength[c[lengthCol]].push_back(v);
            else
                cropByLength[c[lengthCol]].push_back(v);
        }
        cpu += std::clock() - start;
    }
    auto summary = [](const std::vector<double> &v) {
        double mean = 0;
        for (double x : v)
            mean += x / double(v.size());
        return QStringLiteral("n %1, mean %2, median %3, p10 %4")
            .arg(v.size())
            .arg(mean, 0, 'f', 3)
            .arg(bench::quantile(v, 0.5), 0, 'f', 3)
            .arg(bench::quantile(v, 0.1), 0, 'f', 3);
    };
    report << QStringLiteral("faces %1; IoU of the drawn hair with the parse's hair: %2")
                  .arg(faces)
                  .arg(parsedIou.empty() ? QStringLiteral("none") : summary(parsedIou));
    for (const auto &[length, v] : byLength)
        report << QStringLiteral("  labelled %1: %2").arg(length, summary(v));
    report << QStringLiteral(
        "tight crops (crown cut off): IoU of the drawn hair with the parse's hair below the edge: %1")
                  .arg(cropIou.empty() ? QStringLiteral("none") : summary(cropIou));
    for (const auto &[length, v] : cropByLength)
        report << QStringLiteral("  labelled %1: %2").arg(length, summary(v));
    report << QStringLiteral("CPU seconds measuring (detection not counted): %1")
                  .arg(double(cpu) / CLOCKS_PER_SEC, 0, 'f', 1);
    return {{QStringLiteral("report"), QJsonArray::fromStringList(report)}, {QStringLiteral("labelled"), labelled}};
}

} // namespace

TOONFACE_BENCHMARK("likeness.hairregion", hairRegion);
