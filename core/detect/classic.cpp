// The classic pipeline's run (detectClassic): the thesis' steps in order, on a working copy of at
// most 640 pixels, with the figures of each step when asked. The steps themselves: the eye-pair
// search in classiceyes.cpp, the feature edges and regions in classicfeatures.cpp, the points in
// classicpoints.cpp.

#include "detect/classic.h"

#include "detect/classicsteps.h"
#include "i18n/coretext.h"

#include <QElapsedTimer>
#include <QLineF>
#include <QPainter>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace toonface {

namespace {

// skinRelativeIntensity()'s closing: the central rectangle's width over this.
constexpr int kSkinClosingShare = 5;

QImage maskImage(const Mask &m, QColor on, QColor off)
{
    QImage img(m.size, QImage::Format_RGB32);
    for (int y = 0; y < m.size.height(); ++y) {
        auto *row = reinterpret_cast<QRgb *>(img.scanLine(y));
        for (int x = 0; x < m.size.width(); ++x)
            row[x] = m.at(x, y) ? on.rgb() : off.rgb();
    }
    return img;
}

} // namespace

ClassicResult detectClassic(const QImage &input, bool withDebugImages, QRect faceHint)
{
    ClassicResult res;
    QElapsedTimer total, stage;
    total.start();
    stage.start();
    auto lap = [&](const char *name) {
        res.timingMs.insert(QString::fromLatin1(name), stage.nsecsElapsed() / 1e6);
        stage.restart();
    };
    if (input.isNull() || input.width() < 16 || input.height() < 16) {
        res.error = DetectText::tr("The image is too small for the classic method.");
        return res;
    }
    // The pipeline works on a copy at most 640 pixels on its longer side; points go back to
    // the input's pixels at the end.
    const double scale = std::min(1.0, 640.0 / std::max(input.width(), input.height()));
    const QImage image
        = (scale < 1.0 ? input.scaled(QSize(std::lround(input.width() * scale), std::lround(input.height() * scale)),
               Qt::IgnoreAspectRatio, Qt::SmoothTransformation)
                       : input)
              .convertToFormat(QImage::Format_RGB32);
    const QSize size = image.size();

    const Plane I = intensityPlane(image);
    const Plane H = huePlane(image);
    const QRectF hint = faceHint.isValid()
        ? QRectF(faceHint.x() * scale, faceHint.y() * scale, faceHint.width() * scale, faceHint.height() * scale)
        : QRectF();
    // Algorithm 4.1 assumes the face covers the central rectangle. Deviation for real photos
    // (thesis 3.3.2): when no eye pair found with it passes the face check below, the same
    // rectangle is tried higher up the central column (its centre at 1/3, then 1/4 of the
    // height), as portraits frame the face at or above the middle. With a face hint only the
    // middle of the hint is used.
    std::vector<QRect> rects;
    if (hint.isValid()) {
        rects.push_back(
            QRectF(hint.x() + hint.width() / 4, hint.y() + hint.height() / 4, hint.width() / 2, hint.height() / 2)
                .toAlignedRect()
                .intersected(QRect(QPoint(0, 0), size)));
    } else {
        const QRect c = centralRect(size);
        rects.push_back(c);
        for (double centreY : {1.0 / 3.0, 1.0 / 4.0}) {
            const QRect r = c.translated(0, int(std::lround(centreY * size.height())) - c.center().y());
            if (r.top() >= 0 && r != rects.back())
                rects.push_back(r);
        }
    }
    lap("hsi");

    // One try of sections 3.3.2-3.3.5 with one central rectangle and one darkness level k.
    struct Attempt
    {
        bool valid = false;
        QRect rect;
        double k = 1;
        FirstLevel first;
        SecondLevel second;
        RefinedRegions refined;
        std::vector<int> darkLabels;
        std::vector<Region> dark;
        std::vector<EyePairCandidate> candidates, eyes;
    };
    Attempt chosen, thesisChoice;
    double regionsMs = 0, eyePairMs = 0;
    // The intensity itself first, in every central rectangle; then the intensity relative to the
    // person's own skin (below), in every rectangle.
    // A photo without colour has no face region (eq. 3.9 needs hue), and the face checks then pass
    // any wide dark pair (the hair's sides): there the relative pass, whose candidates only those
    // checks vet, is left out.
    bool hasHue = false;
    {
        const QRect c = rects.front();
        int coloured = 0;
        for (int y = c.top(); y <= c.bottom(); ++y)
            for (int x = c.left(); x <= c.right(); ++x)
                coloured += H.at(x, y) < 128.0f;
        hasHue = coloured >= 0.1 * c.width() * c.height();
    }
    for (int pass = 0; pass < (hasHue ? 2 : 1) && !chosen.valid; ++pass) {
        for (const QRect &rect : rects) {
            QElapsedTimer t;
            t.start();
            Attempt a;
            std::vector<Attempt> passing; // the levels on which some pair passed the face checks
            a.rect = rect;
            a.first = firstLevelThreshold(I, rect);
            a.second = secondLevelThreshold(H, a.first.b1, rect);
            a.refined = refineRegions(a.first.b1, a.second.b2);
            regionsMs += t.nsecsElapsed() / 1e6;
            t.restart();
            // Eye pairs on B1 of eq. (3.3) first; where the eyes merge with brows or hair there (real
            // photos, dark make-up), again on stricter darkness levels t = m1 - k s1, k = 1.5, 2, 2.5:
            // the eyes are the darkest features of a face and separate first. Then the same levels on
            // the intensity relative to the person's own skin (skinRelativeIntensity): on dark skin
            // the brows, the eyes and a shaded cheek are all dark on I, and the eyes separate only by
            // how much darker they are than the skin around them (tried when no rectangle found a face
            // on the intensity itself: a drawn or grey face is found there). Its closing is a fifth of the
            // central rectangle wide (about half an eye distance): of 1/3, 1/5, 1/8, 1/12 and 1/16,
            // measured on the shared faces set on plain backgrounds, 1/8 placed the most eye pairs
            // but took a GRID frame's brows for its eyes; 1/5 is the best that keeps every GRID
            // frame's eyes. Every level is tried: a pair that passes the face checks on one level may
            // be a mouth under the eyes that pass them only on another (below).
            struct Level
            {
                const Plane *plane;
                double k;
            };
            const Plane relative = pass == 0 ? Plane {} : skinRelativeIntensity(I, rect.width() / kSkinClosingShare);
            std::vector<Level> levels;
            for (double k : {1.0, 1.5, 2.0, 2.5})
                levels.push_back({pass == 0 ? &I : &relative, k});
            for (const Level &level : levels) {
                const double k = level.k;
                const Plane &P = *level.plane;
                a.k = k;
                const FirstLevel eyeLevel = firstLevelThreshold(P, rect, k);
                const Mask &eyeB1 = eyeLevel.b1;
                a.dark = growRegions(eyeB1, 0, &a.darkLabels);
                a.candidates = eyePairCandidates(a.dark, size);
                // Beyond Chan's rules (3.2): a region that is not clearly darker than its surround (a
                // patch of dark clothing or background that the threshold cut into pieces) is no
                // eye; "clearly": by half the spread s1 of the central rectangle's intensity. A loop
                // wider than 0.6 of the pair's spacing is a spectacle rim (lenses nearly meet at the
                // bridge, ~0.8 of the spacing wide), while an eye outlined by its lids is a loop
                // about 0.45 of it wide.
                std::vector<int> verdict(a.dark.size(), -1), ring(a.dark.size(), -1);
                auto eyeLike = [&](int i) {
                    if (verdict[i] < 0)
                        verdict[i] = darknessContrast(P, a.dark[i], a.darkLabels) >= 0.5 * eyeLevel.s1;
                    return verdict[i] == 1;
                };
                auto rim = [&](int i, double spacing) {
                    if (ring[i] < 0)
                        ring[i] = isRingShaped(a.dark[i], a.darkLabels, size);
                    return ring[i] == 1 && a.dark[i].box.width() > 0.6 * spacing;
                };
                std::erase_if(a.candidates, [&](const EyePairCandidate &c) {
                    const double spacing = QLineF(a.dark[c.left].centroid, a.dark[c.right].centroid).length();
                    return !eyeLike(c.left) || !eyeLike(c.right) || rim(c.left, spacing) || rim(c.right, spacing);
                });
                if (hint.isValid()) {
                    const QRectF upper(hint.x(), hint.y(), hint.width(), 0.6 * hint.height());
                    std::erase_if(a.candidates, [&](const EyePairCandidate &c) {
                        return !upper.contains(a.dark[c.left].centroid) || !upper.contains(a.dark[c.right].centroid);
                    });
                }
                // Knowledge beyond eq. (3.5): brows and spectacle rims pair as well as eyes do and are
                // larger, so a pair gives way to a pair that lies just below it (as wide apart, 0.7 ..
                // 1.3 times; 0.1 d .. 0.7 d lower, horizontally aligned) or inside its two boxes.
                a.eyes.clear();
                for (const auto &c : a.candidates) {
                    const QPointF pa = a.dark[c.left].centroid, pb = a.dark[c.right].centroid;
                    const double dist = QLineF(pa, pb).length();
                    bool hasBelow = false;
                    for (const auto &o : a.candidates) {
                        const QPointF oa = a.dark[o.left].centroid, ob = a.dark[o.right].centroid;
                        auto below = [&](QPointF top, QPointF bottom) {
                            return bottom.y() - top.y() > 0.1 * dist && bottom.y() - top.y() < 0.7 * dist
                                && std::abs(bottom.x() - top.x()) < 0.3 * dist;
                        };
                        if (&o == &c)
                            continue;
                        // A pair nested in this one's boxes (eyes inside spectacle rims, whose
                        // centroids lie farther apart, out toward the temples) wins at any spacing.
                        const bool inside
                            = QRectF(a.dark[c.left].box).contains(oa) && QRectF(a.dark[c.right].box).contains(ob);
                        const double ratio = QLineF(oa, ob).length() / std::max(dist, 1e-9);
                        if (inside || (ratio >= 0.7 && ratio <= 1.3 && below(pa, oa) && below(pb, ob)))
                            hasBelow = true;
                    }
                    if (!hasBelow)
                        a.eyes.push_back(c);
                }
                if (a.eyes.empty())
                    continue;
                a.valid = true;
                if (!thesisChoice.valid)
                    thesisChoice = a;
                // The face check (eyePairInFace): the eyes have the nose, mouth and chin of F_final
                // below them; the best-scoring pair that passes wins.
                std::erase_if(a.eyes, [&](const EyePairCandidate &c) {
                    const QPointF l = a.dark[c.left].centroid, r = a.dark[c.right].centroid;
                    return !eyePairInFace(a.refined.face, l, r) || mouthRowContrast(I, l, r) < kMinMouthRowContrast;
                });
                if (!a.eyes.empty())
                    passing.push_back(a);
            }
            if (!passing.empty()) {
                // A passing pair that lies below another passing pair (of any level), as far below as
                // a mouth lies below the eyes (0.6 .. 1.6 of the upper pair's spacing) and no wider
                // apart than it, is the mouth's two halves or the nostrils under the eyes (a smile's
                // dark corners separate on a level where the eyes still merge with the brows, and
                // score higher by eq. (3.5) than the eyes): the upper pair is the eyes.
                auto geometry = [](const Attempt &at, const EyePairCandidate &c) {
                    const QPointF l = at.dark[c.left].centroid, r = at.dark[c.right].centroid;
                    return std::pair {(l + r) / 2, QLineF(l, r).length()};
                };
                size_t best = 0, bestPair = 0;
                for (bool moved = true; moved;) {
                    moved = false;
                    const auto [lm, ls] = geometry(passing[best], passing[best].eyes[bestPair]);
                    for (size_t j = 0; j < passing.size() && !moved; ++j) {
                        for (size_t o = 0; o < passing[j].eyes.size() && !moved; ++o) {
                            const auto [hm, hs] = geometry(passing[j], passing[j].eyes[o]);
                            const double drop = lm.y() - hm.y();
                            if (ls <= 1.05 * hs && drop >= 0.6 * hs && drop <= 1.6 * hs
                                && std::abs(lm.x() - hm.x()) < 0.5 * hs) {
                                best = j;
                                bestPair = o;
                                moved = true;
                            }
                        }
                    }
                }
                chosen = std::move(passing[best]);
                std::rotate(chosen.eyes.begin(), chosen.eyes.begin() + long(bestPair),
                    chosen.eyes.begin() + long(bestPair) + 1);
            }
            eyePairMs += t.nsecsElapsed() / 1e6;
            if (chosen.valid)
                break;
        }
    }
    res.eyePairInFace = chosen.valid;
    if (!chosen.valid)
        chosen = std::move(thesisChoice); // no pair passes: the thesis' own choice, if any
    if (!chosen.valid) {
        // Nothing at all: the figures show the thesis' first try.
        chosen.rect = rects.front();
        chosen.first = firstLevelThreshold(I, chosen.rect);
        chosen.second = secondLevelThreshold(H, chosen.first.b1, chosen.rect);
        chosen.refined = refineRegions(chosen.first.b1, chosen.second.b2);
        chosen.dark = growRegions(chosen.first.b1, 0, &chosen.darkLabels);
    }
    res.timingMs.insert(QStringLiteral("regions"), regionsMs);
    const FirstLevel &first = chosen.first;
    const SecondLevel &second = chosen.second;
    const RefinedRegions &refined = chosen.refined;
    const std::vector<Region> &dark = chosen.dark;
    const std::vector<int> &darkLabels = chosen.darkLabels;
    const std::vector<EyePairCandidate> &candidates = chosen.candidates, &eyes = chosen.eyes;
    res.t1 = first.t1;
    res.eyeLevelK = chosen.k;
    res.centralRect = chosen.rect;
    if (withDebugImages) {
        res.debugImages.insert(QStringLiteral("classic-b1"), first.b1.toImage());
        res.debugImages.insert(QStringLiteral("classic-b2"), second.b2.toImage());
        res.debugImages.insert(QStringLiteral("classic-b3"), refined.b3.toImage());
        QImage fh = maskImage(refined.face, QColor(230, 190, 160), QColor(40, 60, 120));
        for (int y = 0; y < size.height(); ++y)
            for (int x = 0; x < size.width(); ++x)
                if (refined.hair.at(x, y))
                    fh.setPixel(x, y, qRgb(90, 50, 20));
        res.debugImages.insert(QStringLiteral("classic-face-hair"), fh);
    }
    res.candidateCount = int(candidates.size());
    if (withDebugImages) {
        QImage img = image;
        QPainter p(&img);
        p.setPen(QPen(Qt::white, 1, Qt::DashLine));
        p.drawRect(chosen.rect);
        p.setPen(QPen(Qt::yellow, 1));
        for (const auto &c : candidates) {
            p.drawRect(dark[c.left].box);
            p.drawRect(dark[c.right].box);
            p.drawLine(dark[c.left].centroid, dark[c.right].centroid);
        }
        if (!eyes.empty()) {
            p.setPen(QPen(Qt::red, 2));
            p.drawRect(dark[eyes.front().left].box);
            p.drawRect(dark[eyes.front().right].box);
        }
        p.end();
        res.debugImages.insert(QStringLiteral("classic-eye-pairs"), img);
    }
    res.timingMs.insert(QStringLiteral("eyePair"), eyePairMs);
    stage.restart();
    if (eyes.empty()) {
        res.error = DetectText::tr("No eye pair was found (the classic method needs a large frontal face "
                                   "on a plain background).");
        return res;
    }

    const Region *eyeRegion[2] = {&dark[eyes.front().left], &dark[eyes.front().right]};
    if (!res.eyePairInFace) {
        // Which of the face checks the thesis' own pair fails, for a caller that refuses it.
        const QPointF l = eyeRegion[0]->centroid, r = eyeRegion[1]->centroid;
        PairReach reach;
        eyePairInFace(refined.face, l, r, &reach);
        const double mouth = mouthRowContrast(I, l, r);
        QStringList failed;
        if (reach.below <= 0 && reach.side <= 0)
            failed << DetectText::tr("the point between the eyes is not in the face region");
        else if (reach.below < kMinReachBelow)
            failed << DetectText::tr("the face region reaches %1 eye distances below it (%2 needed)")
                          .arg(reach.below, 0, 'f', 2)
                          .arg(kMinReachBelow);
        if ((reach.below > 0 || reach.side > 0) && (reach.side < kMinReachSide || reach.side > kMaxReachSide))
            failed << DetectText::tr("%1 eye distances to its nearer side (%2 .. %3 needed)")
                          .arg(reach.side, 0, 'f', 2)
                          .arg(kMinReachSide)
                          .arg(kMaxReachSide);
        if (mouth < kMinMouthRowContrast)
            failed << DetectText::tr("no mouth row below it (the darkest row is %1% darker than the median, %2% "
                                     "needed)")
                          .arg(int(std::lround(100 * mouth)))
                          .arg(int(std::lround(100 * kMinMouthRowContrast)));
        res.faceCheck
            = DetectText::tr("the best eye pair by eq. (3.5), at (%1, %2) and (%3, %4), has no face around it: %5")
                  .arg(std::lround(l.x() / scale))
                  .arg(std::lround(l.y() / scale))
                  .arg(std::lround(r.x() / scale))
                  .arg(std::lround(r.y() / scale))
                  .arg(joinReasons(failed));
    }
    for (int k = 0; k < 2; ++k) {
        const Region &r = *eyeRegion[k];
        res.eyeRegions[k] = r.box;
        Mask m {size, std::vector<std::uint8_t>(size_t(size.width()) * size.height(), 0)};
        for (int y = r.box.top(); y <= r.box.bottom(); ++y)
            for (int x = r.box.left(); x <= r.box.right(); ++x)
                m.at(x, y) = darkLabels[size_t(y) * size.width() + x] == r.label;
        res.eyeballs[k] = detectEyeball(m, r.box);
        // Deviation from 3.4.1 for light irises: the dark points are then only the lids and
        // lashes, and the largest disc of them lies at the thick outer corner, not on the iris.
        // A frontal eye looks ahead, its iris in the middle of its outline: a circle found in
        // the outer quarters of the region's columns is replaced by the centre of the region's
        // box (the outline's centre), keeping the radius.
        if (std::abs(res.eyeballs[k].centre.x() - QRectF(r.box).center().x()) > r.box.width() / 4.0)
            res.eyeballs[k].centre = QRectF(r.box).center();
    }
    const Eyeball &ebL = res.eyeballs[0], &ebR = res.eyeballs[1];
    res.d = QLineF(ebL.centre, ebR.centre).length();
    const double d = res.d;
    res.eyeMid = (ebL.centre + ebR.centre) / 2;
    const QPointF mid = res.eyeMid;
    res.square = QRectF(mid.x() - d, mid.y() - d / 2, 2 * d, 2 * d);
    const QRect square = res.square.toAlignedRect().intersected(QRect(QPoint(0, 0), size));
    lap("eyeballs");
    if (withDebugImages) {
        QImage img = image;
        QPainter p(&img);
        p.setRenderHint(QPainter::Antialiasing);
        p.setPen(QPen(Qt::green, 1.5));
        for (const Eyeball &e : res.eyeballs)
            p.drawEllipse(e.centre, e.radius, e.radius);
        p.drawLine(ebL.centre, ebR.centre);
        p.setPen(QPen(Qt::red, 1.5));
        p.drawRect(res.square);
        p.end();
        res.debugImages.insert(QStringLiteral("classic-eyeballs"), img);
    }

    res.divEE = ebL.centre.y() - ebL.height() / 2 - 1;
    res.divEN = mid.y() + d / 3;
    // Div_NM: the thesis speculates EyeMid.y + d "by an experimental result"; faces vary
    // (a short face puts the upper lip above that line, and the mouth search then starts inside
    // the lips). Where the eye pair's mouth row is clear (mouthRowContrast), the line goes a
    // fifth of d above it (between the nose's base and the upper lip), never within d/4 of
    // Div_EN.
    res.divNM = mid.y() + d;
    {
        double row = 0;
        if (mouthRowContrast(I, ebL.centre, ebR.centre, &row) >= kMinMouthRowContrast)
            res.divNM = std::max(res.divEN + d / 4, mid.y() + row - 0.2 * d);
    }
    // Algorithm 4.5: Sobel edges, mirrored about the eyes' axis inside the square, then Tsai
    // per horizontal part.
    const FeatureEdges featureEdgeImage = featureEdges(I, ebL.centre, ebR.centre, res.divEE, res.divEN, res.divNM);
    const Mask &edges = featureEdgeImage.edges;
    res.edgeThresholds = featureEdgeImage.thresholds;
    lap("edges");
    if (withDebugImages) {
        QImage img = edges.toImage().convertToFormat(QImage::Format_RGB32);
        QPainter p(&img);
        p.setPen(QPen(Qt::red, 1));
        for (double y : {res.divEE, res.divEN, res.divNM})
            p.drawLine(QPointF(square.left(), y), QPointF(square.right(), y));
        p.setPen(QPen(Qt::green, 1));
        p.drawRect(res.square);
        p.end();
        res.debugImages.insert(QStringLiteral("classic-edges"), img);
    }

    // Algorithm 4.6 with the restrictions: inside the square; nose and mouth between the
    // eyeball centres; each feature kept between its division lines.
    const double hL = std::max(ebL.height(), 2.0);
    const QRectF eyeInit(QPointF(ebL.centre.x() - hL, ebL.centre.y() - 0.5 * hL),
        QPointF(ebL.centre.x() + hL, ebL.centre.y() + 0.5 * hL));
    // "The eye range translated above Div_EE": the same columns, ending at Div_EE, at least d/3
    // high so that brows set well above the eyes are still reached.
    const double browH = std::max(eyeInit.height(), d / 3);
    const QRectF browInit(QPointF(eyeInit.left(), res.divEE - browH), QPointF(eyeInit.right(), res.divEE));
    const QRectF noseInit(
        QPointF(ebL.centre.x(), res.divEN), QPointF(ebR.centre.x(), res.divEN + 0.7 * (res.divNM - res.divEN)));
    const QRectF mouthInit(QPointF(ebL.centre.x(), res.divNM), QPointF(ebR.centre.x(), res.divNM + d / 3));
    auto rows = [&](double top, double bottom, double left, double right) {
        return QRect(
            QPoint(int(std::ceil(left)), int(std::ceil(top))), QPoint(int(std::floor(right)), int(std::floor(bottom))))
            .intersected(square);
    };
    const FeatureRegion eye
        = growFeature(edges, eyeInit.toAlignedRect(), rows(res.divEE + 1, res.divEN, square.left(), mid.x()));
    const FeatureRegion brow
        = growFeature(edges, browInit.toAlignedRect(), rows(square.top(), res.divEE, square.left(), mid.x()));
    const FeatureRegion nose
        = growFeature(edges, noseInit.toAlignedRect(), rows(res.divEN, res.divNM, ebL.centre.x(), ebR.centre.x()));
    const FeatureRegion mouth = growFeature(
        edges, mouthInit.toAlignedRect(), rows(res.divNM, square.bottom(), ebL.centre.x(), ebR.centre.x()));
    res.eyeRegion = eye.box;
    res.browRegion = brow.box;
    res.noseRegion = nose.box;
    res.mouthRegion = mouth.box;
    res.noseCut = centralVerticalCut(I, nose.box);
    res.mouthCut = centralVerticalCut(I, mouth.box);
    lap("features");
    if (withDebugImages) {
        QImage img = image;
        QPainter p(&img);
        p.setPen(QPen(Qt::yellow, 1, Qt::DashLine));
        for (const QRectF &r : {eyeInit, browInit, noseInit, mouthInit})
            p.drawRect(r);
        p.setPen(QPen(Qt::cyan, 1.5));
        for (const QRectF &r : {res.eyeRegion, res.browRegion, res.noseRegion, res.mouthRegion})
            p.drawRect(r);
        p.setPen(QPen(Qt::magenta, 1));
        p.drawLine(QPointF(res.noseCut, res.noseRegion.top()), QPointF(res.noseCut, res.noseRegion.bottom()));
        p.drawLine(QPointF(res.mouthCut, res.mouthRegion.top()), QPointF(res.mouthCut, res.mouthRegion.bottom()));
        p.end();
        res.debugImages.insert(QStringLiteral("classic-feature-regions"), img);
    }

    // Section 4.3.1 (classicpoints.cpp).
    FaceModel face = placeFeaturePoints({eye, brow, nose, mouth}, res, size);
    lap("featurePoints");

    // Section 4.3.2 (classicpoints.cpp).
    placeOutline(&face, refined, size, &res);
    lap("outline");

    if (withDebugImages) {
        QImage img = image;
        QPainter p(&img);
        p.setRenderHint(QPainter::Antialiasing);
        p.setPen(Qt::NoPen);
        for (int i = 0; i < kPointCount; ++i) {
            p.setBrush(pointTable()[i].group == PointGroup::Hair ? Qt::magenta : Qt::green);
            p.drawEllipse(face.point(i), 2.0, 2.0);
        }
        p.setPen(QPen(Qt::cyan, 1));
        p.drawLine(QPointF(res.cheekLeft, 0), QPointF(res.cheekLeft, size.height()));
        p.drawLine(QPointF(res.cheekRight, 0), QPointF(res.cheekRight, size.height()));
        p.end();
        res.debugImages.insert(QStringLiteral("classic-points"), img);
    }

    // Back to the input's pixels.
    if (scale < 1.0) {
        const double k = 1.0 / scale;
        for (int i = 0; i < kPointCount; ++i)
            face.setPoint(i, face.point(i) * k);
        for (auto &r : res.eyeRegions)
            r = QRectF(r.topLeft() * k, r.size() * k);
        for (auto &e : res.eyeballs) {
            e.centre *= k;
            e.radius *= k;
        }
        res.d *= k;
        res.eyeMid *= k;
        for (QRectF *r : {&res.square, &res.browRegion, &res.eyeRegion, &res.noseRegion, &res.mouthRegion})
            *r = QRectF(r->topLeft() * k, r->size() * k);
        for (double *v :
            {&res.divEE, &res.divEN, &res.divNM, &res.noseCut, &res.mouthCut, &res.cheekLeft, &res.cheekRight})
            *v *= k;
    }
    // Searches that end on the image's edge may round just outside it.
    for (int i = 0; i < kPointCount; ++i)
        face.setPoint(i,
            QPointF(std::clamp(face.point(i).x(), 0.0, input.width() - 1.0),
                std::clamp(face.point(i).y(), 0.0, input.height() - 1.0)));
    face.setImageSize(input.size());
    res.face = face;
    if (!face.isValid()) {
        res.error = DetectText::tr("The classic method found an eye pair but could not place a face around it "
                                   "(a feature collapsed to nothing).");
        res.timingMs.insert(QStringLiteral("total"), total.nsecsElapsed() / 1e6);
        return res;
    }
    res.timingMs.insert(QStringLiteral("total"), total.nsecsElapsed() / 1e6);
    res.ok = true;
    return res;
}

} // namespace toonface
