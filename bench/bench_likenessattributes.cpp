#include "benchmark.h"
#include "crossvalidation.h"
#include "facecache.h"
#include "haircolourreport.h"
#include "likenessage.h"

#include "detect/appearance.h"
#include "detect/browlook.h"
#include "detect/detector.h"
#include "detect/photocolours.h"
#include "face/fapu.h"
#include "io/facejson.h"
#include "render/style.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTextStream>

#include <algorithm>
#include <map>
#include <string>

// likeness.attributes: detection and appearance on every face of faces-attributes (the
// developers' labelled set, research-only: measured here, never shipped), scored against its
// labels. Per decision, precision and recall of what the program decides today, overall and by
// sex, skin tone and age group; facial hair drawn on women and children; the drawn skin's L*
// against the photo's cheeks'. For each decision rule, its thresholds chosen by 5-fold
// stratified cross-validation (fitted on four folds, scored on the fifth) and the held-out
// figures, with the thresholds fitted on all faces (the ones the code ships). The ROC area of
// every measure for every label says which measures are evidence at all.
// TOONFACE_FACE_CACHE=DIR keeps each face's detected points there (re-runs skip detection).

using namespace toonface;
using bench::Counts;

namespace {

struct Labelled
{
    QString file, sex, age, skin, hairLength;
    bool bald = false, beard = false, moustache = false, goatee = false, glasses = false, headwear = false;
    bool detected = false;
    Appearance shipped;
    std::map<std::string, double> m; // the findings' measures
    double drawnL = 0, cheekL = 0;
    QString hairColour; // the label: black, brown, blond, red, grey, none or ?
    QColor drawnHair, drawnSkin, parsedHair;
    bench::HairColourRow hair; // the hair's and the facial hair's colour (haircolourreport.h)
    AgeEvidence ageEvidence;
    BrowLook brows;
};

// CIE L* (D65) of an sRGB colour.
double lStar(const QColor &c)
{
    auto linear = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    const double y = 0.2126 * linear(c.redF()) + 0.7152 * linear(c.greenF()) + 0.0722 * linear(c.blueF());
    return y > 216.0 / 24389.0 ? 116.0 * std::cbrt(y) - 16.0 : y * 24389.0 / 27.0;
}

// The photo's cheeks' L* as the style reads the skin (the same two places), without any balance.
double photoCheekL(const QImage &photo, const FaceModel &face)
{
    const double es0 = face.fapu().es0;
    auto p = [&](const char *id) { return face.point(id); };
    std::vector<double> l;
    for (const QPointF &c :
        {(p("3.4") + p("8.4") + p("5.2") + p("9.2")) / 4.0, (p("3.3") + p("8.3") + p("5.1") + p("9.1")) / 4.0}) {
        const double r = std::max(1.0, 0.07 * es0);
        for (int y = int(c.y() - r); y <= int(c.y() + r); ++y)
            for (int x = int(c.x() - r); x <= int(c.x() + r); ++x)
                if (photo.rect().contains(x, y) && std::hypot(x - c.x(), y - c.y()) <= r)
                    l.push_back(lStar(photo.pixelColor(x, y)));
    }
    return bench::quantile(l, 0.5);
}

void measure(Labelled *row, const QImage &photo, const FaceModel &face)
{
    Style style = Style::preset(QStringLiteral("normal"));
    AppearanceFindings f;
    sampleColours(photo, face, &style, &f);
    row->shipped = style.appearance;
    row->drawnL = lStar(style.components.value(QStringLiteral("face")).fill);
    row->cheekL = photoCheekL(photo, face);
    row->drawnHair = style.components.value(QStringLiteral("hair")).fill;
    row->drawnSkin = style.components.value(QStringLiteral("face")).fill;
    row->parsedHair = f.parsedHair;
    bench::HairColourRow &hair = row->hair;
    hair.shade = bench::hairShadeOfLabel(row->hairColour);
    hair.reading = f.hairReading;
    hair.skin = row->drawnSkin;
    hair.hairDrawn = !style.appearance.bald && !style.appearance.hat;
    hair.drawn = row->drawnHair;
    hair.before = f.parsedHair.isValid() ? f.parsedHair : row->drawnHair;
    hair.bearded = (row->beard || row->moustache || row->goatee)
        && (style.appearance.beard || style.appearance.moustache || style.appearance.goatee);
    hair.beardBefore = f.facialHair;
    hair.beardDrawn = style.components.value(QStringLiteral("beard")).fill;
    row->ageEvidence = f.ageEvidence;
    row->brows = measureBrows(photo, face);
    auto &m = row->m;
    m["glassesScore"] = f.glassesScore;
    m["bridgedDark"] = f.bridgedDark;
    m["moustacheScore"] = f.moustacheScore;
    m["moustacheTexture"] = f.moustacheTexture;
    m["moustacheSpeckle"] = f.moustacheSpeckle;
    m["beardScore"] = f.beardScore;
    m["beardTexture"] = f.beardTexture;
    m["jawScore"] = f.jawScore;
    m["goateeScore"] = f.goateeScore;
    m["baldScore"] = f.baldScore;
    m["skinReach"] = f.skinReach;
    m["crownSeen"] = !f.crownCut && !(f.topCut && f.headHeight < AppearanceFindings::kMinHeadHeight) ? 1.0 : 0.0;
    m["headHeight"] = f.headHeight;
    m["scalpReach"] = f.scalpReach;
    m["crownCut"] = f.crownCut ? 1.0 : 0.0;
    m["hairSeen"] = f.hairSeen ? 1.0 : 0.0;
    m["hairFall"] = f.hairFall;
    m["templeHairSeen"] = f.templeHairSeen ? 1.0 : 0.0;
    m["noHairSeen"] = f.hairSeen || f.templeHairSeen ? 0.0 : 1.0;
    m["fallCut"] = f.fallCut ? 1.0 : 0.0;
    m["roomFall"] = f.roomFall ? 1.0 : 0.0;
    m["templeLighter"] = f.templeLighter;
    m["measuredFall"] = f.measuredFall;
    m["crownSkin"] = f.crownSkin;
    m["templeSkin"] = f.templeSkin;
    m["hairLengthShipped"] = double(int(f.hairLength)); // 0 none, 1 short, 2 medium, 3 long
    m["hatScore"] = f.hatScore;
    m["crownToHair"] = f.crownToHair;
    m["crownToSkin"] = f.crownToSkin;
    m["brimSpread"] = f.brimSpread;
    m["coverSeen"] = f.cover.seen ? 1.0 : 0.0;
    m["coverL"] = f.cover.l;
    m["coverChroma"] = f.cover.chroma;
    m["coverHueOff"] = f.cover.hueOff;
    m["coverToSkin"] = f.cover.toSkin;
    m["coverToBrows"] = f.cover.toBrows;
    m["coverLighter"] = f.cover.lighter;
    m["coverEdgeSpread"] = f.cover.edgeSpread;
    m["coverEdgeHeight"] = f.cover.edgeHeight;
    m["coverSides"] = f.cover.sides;
    m["coverColourScore"] = f.cover.seen ? f.cover.hueOff * f.cover.chroma / 100.0 : 0.0;
    m["coverWhiteL"] = f.cover.seen ? f.cover.l : 0.0;
    const AppearanceEvidence &e = f.evidence;
    m["lipHair"] = e.lipHair;
    m["chinHair"] = e.chinHair;
    m["jawHair"] = e.jawHair;
    m["lipDetail"] = e.lipDetail;
    m["chinDetail"] = e.chinDetail;
    m["jawDetail"] = e.jawDetail;
    m["lipDL"] = e.lipDL;
    m["chinDL"] = e.chinDL;
    m["jawDL"] = e.jawDL;
    m["lipRedLoss"] = e.lipRedLoss;
    m["lipColour"] = e.lipColour;
    m["chinRedLoss"] = e.chinRedLoss;
    m["lowerRedLoss"] = e.lowerRedLoss;
    m["jawRedLoss"] = e.jawRedLoss;
    m["bridgeLine"] = e.bridgeLine;
    m["sideRims"] = e.sideRims;
    m["lowerRims"] = e.lowerRims;
    // How far down the hair outline's lower ends reach, from the eyes' line to the chin's point (1).
    const double eyeY = (face.point("3.6").y() + face.point("3.5").y()) / 2.0;
    const double chin = std::max(1.0, face.point("2.1").y() - eyeY);
    m["hairDrop"] = (std::max(face.point("h.1").y(), face.point("h.19").y()) - eyeY) / chin;
}

std::vector<Labelled> load(QString *error)
{
    const QString data = bench::sharedDataDir();
    const QString dir = data.isEmpty() ? QString() : QDir(data).filePath(QStringLiteral("faces-attributes"));
    QFile tsv(QDir(dir).filePath(QStringLiteral("labels.tsv")));
    if (dir.isEmpty() || !tsv.open(QIODevice::ReadOnly | QIODevice::Text)) {
        *error = QStringLiteral("faces-attributes/labels.tsv not found under the shared data folder");
        return {};
    }
    QTextStream in(&tsv);
    const QStringList header = in.readLine().split(QLatin1Char('\t'));
    auto col = [&](const char *name) { return header.indexOf(QLatin1StringView(name)); };
    std::vector<Labelled> rows;
    while (!in.atEnd()) {
        const QStringList c = in.readLine().split(QLatin1Char('\t'));
        if (c.size() < header.size())
            continue;
        Labelled r;
        auto flag = [&](const char *name) { return c[col(name)] == QLatin1String("1"); };
        r.file = c[col("file")];
        r.sex = c[col("sex")];
        r.age = c[col("age_group")];
        r.skin = c[col("skin")];
        r.hairLength = c[col("hair_length")];
        r.hairColour = c[col("hair_colour")];
        r.bald = flag("bald");
        r.beard = flag("beard");
        r.moustache = flag("moustache");
        r.goatee = flag("goatee");
        r.glasses = flag("glasses");
        r.headwear = flag("headwear");
        const QImage photo(QDir(dir).filePath(r.file));
        if (photo.isNull()) {
            *error = QStringLiteral("%1: not readable").arg(r.file);
            return {};
        }
        if (const auto face = bench::detectCached(photo, QFileInfo(r.file).completeBaseName())) {
            r.detected = true;
            measure(&r, photo, *face);
        }
        rows.push_back(std::move(r));
    }
    return rows;
}

QString figures(const Counts &c)
{
    return QStringLiteral("P %1 R %2 (tp %3 fp %4 fn %5 n %6)")
        .arg(c.precision(), 0, 'f', 2)
        .arg(c.recall(), 0, 'f', 2)
        .arg(c.tp)
        .arg(c.fp)
        .arg(c.fn)
        .arg(c.n());
}

// One decision: its label, which faces it is scored on, what the program decides, and the rule
// whose thresholds are cross-validated.
struct Decision
{
    QString name;
    std::function<bool(const Labelled &)> truth, scored, shipped;
    std::vector<std::string> ruleMeasures; // the measures the rule reads, in its parameters' order
    std::function<bool(const Labelled &, const std::vector<double> &)> rule;
    QString objective; // "f0.5" (precision first) or "accuracy"
};

double objectiveOf(const QString &name, const Counts &c)
{
    if (name == QLatin1String("balanced accuracy"))
        return (c.recall() + (c.tn + c.fp > 0 ? double(c.tn) / (c.tn + c.fp) : 1.0)) / 2.0;
    return name == QLatin1String("accuracy") ? c.accuracy() : c.fBeta(0.5);
}

// Precision and recall (or accuracy) overall and by sex, skin tone and age group.
// With `repeats` > 1, `predicted(split, face)` is each of several fold splits' held-out decision,
// and the counts are pooled over them (each face counted once a split).
QStringList splits(const std::vector<Labelled> &rows, const std::vector<size_t> &scored,
    const std::function<bool(int, size_t)> &predicted, const std::function<bool(size_t)> &truth, bool accuracy,
    int repeats = 1)
{
    QStringList out;
    auto line = [&](const QString &group, const std::function<bool(const Labelled &)> &in) {
        Counts c;
        for (int s = 0; s < repeats; ++s)
            for (size_t i : scored)
                if (in(rows[i]))
                    c.add(predicted(s, i), truth(i));
        if (c.n() == 0)
            return;
        out << (accuracy ? QStringLiteral("  %1: right %2 of %3 (%4)")
                               .arg(group)
                               .arg(c.tp + c.tn)
                               .arg(c.n())
                               .arg(c.accuracy(), 0, 'f', 2)
                         : QStringLiteral("  %1: %2").arg(group, figures(c)));
    };
    line(QStringLiteral("all"), [](const Labelled &) { return true; });
    for (const char *s : {"m", "f"})
        line(QStringLiteral("sex %1").arg(QLatin1StringView(s)),
            [&](const Labelled &r) { return r.sex == QLatin1StringView(s); });
    for (const char *s : {"light", "medium", "dark"})
        line(QStringLiteral("skin %1").arg(QLatin1StringView(s)),
            [&](const Labelled &r) { return r.skin == QLatin1StringView(s); });
    for (const char *s : {"child", "young", "adult", "elderly"})
        line(QStringLiteral("age %1").arg(QLatin1StringView(s)),
            [&](const Labelled &r) { return r.age == QLatin1StringView(s); });
    return out;
}

} // namespace

namespace {

bool anyFacialHair(const Appearance &a)
{
    return a.moustache || a.beard || a.goatee;
}

// The rules as appearance.cpp decides, with their thresholds as parameters (in the order of
// ruleMeasures' names) and the constants the code ships.
bool lipRule(const Labelled &r, const std::vector<double> &t)
{
    const double lip = r.m.at("lipRedLoss"), chin = r.m.at("chinRedLoss");
    return (r.m.at("lipColour") >= t[0] && std::max(lip, chin) >= t[1]) || r.m.at("lipDL") <= -t[2];
}

bool chinRule(const Labelled &r, const std::vector<double> &t)
{
    return (r.m.at("chinRedLoss") >= t[0] && r.m.at("chinDetail") >= t[1]) || r.m.at("chinDL") <= -t[2];
}

std::vector<Decision> decisions()
{
    using A = AppearanceFindings;
    auto all = [](const Labelled &) { return true; };
    auto m = [](const Labelled &r, const char *k) { return r.m.at(k); };
    std::vector<Decision> d;
    // Facial hair (any) is the moustache's or the beard's rule: its held-out figures are theirs.
    d.push_back({QStringLiteral("moustache"), [](const Labelled &r) { return r.moustache; }, all,
        [](const Labelled &r) { return r.shipped.moustache; }, {"lipColour", "redLossSure", "-lipDL"}, lipRule,
        QStringLiteral("f0.5")});
    d.push_back({QStringLiteral("beard (incl. goatee)"), [](const Labelled &r) { return r.beard; }, all,
        [](const Labelled &r) { return r.shipped.beard || r.shipped.goatee; }, {"chinRedLoss", "chinDetail", "-chinDL"},
        chinRule, QStringLiteral("f0.5")});
    d.push_back({QStringLiteral("facial hair"), [](const Labelled &r) { return r.beard || r.moustache || r.goatee; },
        all, [](const Labelled &r) { return anyFacialHair(r.shipped); }, {}, {}, QStringLiteral("f0.5")});
    // Among the chins found hairy: a full beard (the jaw's sides too) or a goatee.
    d.push_back(
        {QStringLiteral("full beard, of the chins found hairy"), [](const Labelled &r) { return r.beard && !r.goatee; },
            [](const Labelled &r) {
                return chinRule(r, {A::kChinRedLoss, A::kChinDetail, A::kChinDarker});
            },
            [](const Labelled &r) { return r.shipped.beard; }, {"jawRedLoss"},
            [m](const Labelled &r, const std::vector<double> &t) {
                return m(r, "jawRedLoss") >= t[0] || m(r, "jawDL") <= -A::kChinDarker;
            },
            QStringLiteral("balanced accuracy")});
    d.push_back({QStringLiteral("glasses"), [](const Labelled &r) { return r.glasses; }, all,
        [](const Labelled &r) { return r.shipped.glasses != GlassesShape::None; },
        {"bridgeLine", "lowerRims", "sideRims"},
        [m](const Labelled &r, const std::vector<double> &t) {
            return (m(r, "bridgeLine") >= t[0] && (m(r, "lowerRims") >= t[1] || m(r, "sideRims") >= t[2]))
                || m(r, "glassesScore") >= A::kGlassesThreshold;
        },
        QStringLiteral("f0.5")});
    d.push_back({QStringLiteral("headwear"), [](const Labelled &r) { return r.headwear; }, all,
        [](const Labelled &r) { return r.shipped.hat; }, {"coverColourScore", "coverWhiteL", "coverLighter"},
        // (18 of the 21 headwear faces are crops whose crown the photo cuts off, where the crown's
        // rules (hatScore, a brim) decide nothing: what the parse sees over the forehead decides,
        // a colour no hair has or white far lighter than the brows.)
        [m](const Labelled &r, const std::vector<double> &t) {
            return m(r, "hatScore") >= A::kHatThreshold || m(r, "coverColourScore") >= t[0]
                || (m(r, "coverWhiteL") >= t[1] && m(r, "coverLighter") >= t[2]);
        },
        QStringLiteral("accuracy")});
    d.push_back({QStringLiteral("bald"), [](const Labelled &r) { return r.bald; }, all,
        [](const Labelled &r) { return r.shipped.bald; }, {"scalpReach", "headHeight", "baldScore", "skinReach"},
        [m](const Labelled &r, const std::vector<double> &t) {
            // A crown the parse sees decides by its skin; otherwise the outline's measures (a crown
            // the photo cuts off keeps its own rule; its measures are 0 here). All nine bald faces of
            // faces-attributes are such crops: for a crown seen this set holds no bald head, and the
            // fit can only say how high the haired crowns' skin share reaches.
            if (m(r, "crownSeen") == 1.0)
                return m(r, "scalpReach") >= t[0] && m(r, "headHeight") >= t[1];
            return m(r, "baldScore") >= t[2] || (m(r, "skinReach") >= t[3] && m(r, "skinReach") <= 1.3);
        },
        QStringLiteral("accuracy")});
    return d;
}

// How many random stratified fold splits a decision's held-out figures are pooled over: with one
// split, a single face moving fold swings a rare label's held-out precision or recall by ±0.15.
constexpr int kSplits = 10;

// The rule's held-out predictions for each of `repeats` random fold splits (each face decided by
// thresholds fitted on the other folds of that split) and the thresholds fitted on all faces.
std::pair<std::vector<std::vector<bool>>, std::vector<double>> crossValidate(
    const Decision &d, const std::vector<Labelled> &rows, const std::vector<size_t> &scored, const int k, int repeats)
{
    std::vector<bool> truth(rows.size());
    std::vector<int> label(scored.size());
    for (size_t i = 0; i < rows.size(); ++i)
        truth[i] = d.truth(rows[i]);
    for (size_t i = 0; i < scored.size(); ++i)
        label[i] = truth[scored[i]];
    bench::Rule rule;
    for (const std::string &name : d.ruleMeasures) {
        // A parameter that is no measure of its own (a second threshold on a measure) takes the
        // candidates of the lip's redness loss.
        // ("-name": the measure negated.)
        const bool negated = name.front() == '-';
        const std::string own = negated ? name.substr(1) : name;
        const std::string measure = rows[scored.front()].m.count(own) ? own : std::string("lipRedLoss");
        std::vector<double> v;
        for (size_t i : scored)
            v.push_back(negated ? -rows[i].m.at(measure) : rows[i].m.at(measure));
        rule.candidates.push_back(bench::thresholdsFrom(v, 24));
    }
    rule.decide = [&](size_t r, const std::vector<double> &t) { return d.rule(rows[r], t); };
    auto objective = [&](const Counts &c) { return objectiveOf(d.objective, c); };
    std::vector<std::vector<bool>> heldOut(size_t(repeats), std::vector<bool>(rows.size(), false));
    for (int s = 0; s < repeats; ++s) {
        // The first split is the one the single-split figures were always printed for.
        const std::vector<int> fold = bench::stratifiedFolds(label, k, 20261128u + unsigned(s));
        for (int f = 0; f < k; ++f) {
            std::vector<size_t> train, test;
            for (size_t i = 0; i < scored.size(); ++i)
                (fold[i] == f ? test : train).push_back(scored[i]);
            const std::vector<double> t = bench::fitRule(rule, train, truth, objective);
            for (size_t r : test)
                heldOut[size_t(s)][r] = d.rule(rows[r], t);
        }
    }
    return {heldOut, bench::fitRule(rule, scored, truth, objective)};
}

int lengthClass(const QString &label)
{
    const QStringList names {QStringLiteral("short"), QStringLiteral("medium"), QStringLiteral("long")};
    return int(names.indexOf(label));
}

// Hair length (short, medium, long) from how far down the hair reaches (`measure`: the outline's
// hairDrop, or the parse's hairFall): two thresholds, cross-validated for accuracy on the faces
// whose hair length is labelled and not none (and, with `seenOnly`, whose crown showed the parse
// its hair).
// The shipped hair length against the labels (short, medium, long; faces not drawn bald).
QStringList shippedHairLength(const std::vector<Labelled> &rows, const std::vector<size_t> &detected)
{
    int confusion[3][3] = {}, right = 0, n = 0;
    for (size_t i : detected) {
        const int truth = lengthClass(rows[i].hairLength);
        const int decided = int(rows[i].m.at("hairLengthShipped")) - 1;
        if (truth < 0 || decided < 0)
            continue;
        ++confusion[truth][decided];
        right += truth == decided;
        ++n;
    }
    QStringList out;
    out << QStringLiteral("hair length — as shipped: right %1 of %2 (%3); rows labelled short/medium/long, "
                          "columns decided:")
               .arg(right)
               .arg(n)
               .arg(n > 0 ? double(right) / n : 0.0, 0, 'f', 2);
    for (int c = 0; c < 3; ++c)
        out << QStringLiteral("  %1 %2 %3").arg(confusion[c][0], 4).arg(confusion[c][1], 4).arg(confusion[c][2], 4);
    return out;
}

// With `lighter` (a tight crop's temple sample's L* over the cheeks', headparse.h), a third
// threshold: from it the sample is the room and the face short-haired (HeadParse::roomFall).
QStringList hairLength(const std::vector<Labelled> &rows, const std::vector<size_t> &detected, int k,
    const char *measure, const char *onlyWhere, const char *lighter = nullptr)
{
    std::vector<size_t> scored;
    std::vector<int> label;
    for (size_t i : detected)
        if (lengthClass(rows[i].hairLength) >= 0 && !rows[i].shipped.bald
            && (!onlyWhere || rows[i].m.at(onlyWhere) == 1.0)) {
            scored.push_back(i);
            label.push_back(lengthClass(rows[i].hairLength));
        }
    if (scored.empty())
        return {};
    auto classOf = [&](size_t r, const std::vector<double> &t) {
        const double drop = rows[r].m.at(measure);
        if (lighter && rows[r].m.at(lighter) >= t[2])
            return 0;
        return drop < t[0] ? 0 : drop < t[1] ? 1 : 2;
    };
    std::vector<double> v, l;
    for (size_t i : scored) {
        v.push_back(rows[i].m.at(measure));
        if (lighter)
            l.push_back(rows[i].m.at(lighter));
    }
    // Counted as "right or not" (every face a positive): recall is the share right.
    std::vector<std::vector<double>> candidates {bench::thresholdsFrom(v, 24), bench::thresholdsFrom(v, 24)};
    if (lighter) { // (tried from the highest down: of thresholds equally right, the fewest faces called the room)
        candidates.push_back(bench::thresholdsFrom(l, 24));
        std::reverse(candidates.back().begin(), candidates.back().end());
    }
    bench::Rule rule {candidates,
        [&](size_t r, const std::vector<double> &t) { return classOf(r, t) == lengthClass(rows[r].hairLength); }};
    const std::vector<bool> truth(rows.size(), true);
    auto objective = [](const Counts &c) { return c.recall(); };
    const std::vector<int> fold = bench::stratifiedFolds(label, k);
    int confusion[3][3] = {};
    for (int f = 0; f < k; ++f) {
        std::vector<size_t> train, test;
        for (size_t i = 0; i < scored.size(); ++i)
            (fold[i] == f ? test : train).push_back(scored[i]);
        const std::vector<double> t = bench::fitRule(rule, train, truth, objective);
        for (size_t r : test)
            ++confusion[lengthClass(rows[r].hairLength)][classOf(r, t)];
    }
    const std::vector<double> all = bench::fitRule(rule, scored, truth, objective);
    const int right = confusion[0][0] + confusion[1][1] + confusion[2][2];
    QStringList out;
    out << QStringLiteral("hair length — %4%5, held-out folds (%1-fold, objective accuracy; fitted on all: %2, %3%6):")
               .arg(k)
               .arg(all[0], 0, 'g', 4)
               .arg(all[1], 0, 'g', 4)
               .arg(QLatin1StringView(measure),
                   onlyWhere ? QStringLiteral(" (where %1)").arg(QLatin1StringView(onlyWhere)) : QString(),
                   lighter
                       ? QStringLiteral("; the room from %1 %2").arg(QLatin1StringView(lighter)).arg(all[2], 0, 'g', 4)
                       : QString());
    out << QStringLiteral("  right %1 of %2 (%3); rows labelled short/medium/long, columns decided:")
               .arg(right)
               .arg(scored.size())
               .arg(double(right) / double(scored.size()), 0, 'f', 2);
    for (int c = 0; c < 3; ++c)
        out << QStringLiteral("  %1 %2 %3").arg(confusion[c][0], 4).arg(confusion[c][1], 4).arg(confusion[c][2], 4);
    return out;
}

QJsonObject attributes()
{
    QString error;
    const std::vector<Labelled> rows = load(&error);
    if (rows.empty())
        return {{QStringLiteral("error"), error}};
    std::vector<size_t> detected;
    for (size_t i = 0; i < rows.size(); ++i)
        if (rows[i].detected)
            detected.push_back(i);
    QStringList report;
    report << QStringLiteral("faces %1, detected %2").arg(rows.size()).arg(detected.size());
    const int k = 5;
    std::map<QString, std::vector<std::vector<bool>>> heldOutOf; // the moustache's and the beard's
    for (const Decision &d : decisions()) {
        std::vector<size_t> scored;
        for (size_t i : detected)
            if (d.scored(rows[i]))
                scored.push_back(i);
        const bool accuracy = d.objective.endsWith(QLatin1String("accuracy"));
        report << d.name + QStringLiteral(" — as shipped:");
        report << splits(
            rows, scored, [&](int, size_t i) { return d.shipped(rows[i]); }, [&](size_t i) { return d.truth(rows[i]); },
            accuracy);
        // Pooled over kSplits fold splits; a rule of four thresholds (bald: 24^4 candidates a fit)
        // over one, which alone takes as long as the others' ten.
        const int repeats = d.ruleMeasures.size() <= 3 ? kSplits : 1;
        auto [heldOut, fitted] = d.rule ? crossValidate(d, rows, scored, k, repeats)
                                        : std::pair<std::vector<std::vector<bool>>, std::vector<double>> {};
        if (!d.rule) {
            // Facial hair (any): the moustache's or the beard's held-out decision, split by split.
            heldOut.assign(size_t(kSplits), std::vector<bool>(rows.size(), false));
            for (const auto &[name, decided] : heldOutOf)
                for (size_t s = 0; s < heldOut.size(); ++s)
                    for (size_t i = 0; i < rows.size(); ++i)
                        heldOut[s][i] = heldOut[s][i] || decided[s][i];
        } else if (d.name == QLatin1String("moustache") || d.name.startsWith(QLatin1String("beard"))) {
            heldOutOf[d.name] = heldOut;
        }
        QStringList names;
        for (size_t p = 0; p < fitted.size(); ++p)
            names << QStringLiteral("%1 %2").arg(QString::fromStdString(d.ruleMeasures[p])).arg(fitted[p], 0, 'g', 4);
        const int pooled = int(heldOut.size());
        report << d.name
                + QStringLiteral(" — rule, held-out folds (%1-fold, pooled over %2 random splits, objective %3; "
                                 "fitted on all: %4):")
                      .arg(k)
                      .arg(pooled)
                      .arg(d.objective, names.join(QStringLiteral(", ")));
        report << splits(
            rows, scored, [&](int s, size_t i) { return bool(heldOut[size_t(s)][i]); },
            [&](size_t i) { return d.truth(rows[i]); }, accuracy, pooled);
        if (d.name == QLatin1String("facial hair")) {
            // Faces drawn with facial hair, counted once a split, over the splits (a mean a split).
            int women = 0, children = 0;
            for (const std::vector<bool> &decided : heldOut)
                for (size_t i : scored) {
                    women += decided[i] && rows[i].sex == QLatin1String("f");
                    children += decided[i] && rows[i].age == QLatin1String("child");
                }
            report << QStringLiteral("  held out: drawn on women %1, on children %2 (a split, mean over %3)")
                          .arg(double(women) / pooled, 0, 'f', 1)
                          .arg(double(children) / pooled, 0, 'f', 1)
                          .arg(pooled);
        }
    }
    report << shippedHairLength(rows, detected);
    report << hairLength(rows, detected, k, "hairDrop", nullptr);
    report << hairLength(rows, detected, k, "hairDrop", "hairSeen");
    report << hairLength(rows, detected, k, "hairDrop", "noHairSeen");
    report << hairLength(rows, detected, k, "hairFall", "hairSeen");
    report << hairLength(rows, detected, k, "hairFall", "templeHairSeen");
    report << hairLength(rows, detected, k, "measuredFall", "templeHairSeen", "templeLighter");
    // Facial hair drawn on women and children.
    int onWomen = 0, onChildren = 0;
    for (size_t i : detected) {
        if (!anyFacialHair(rows[i].shipped))
            continue;
        onWomen += rows[i].sex == QLatin1String("f");
        onChildren += rows[i].age == QLatin1String("child");
    }
    report << QStringLiteral("facial hair drawn on women %1, on children %2").arg(onWomen).arg(onChildren);
    {
        std::vector<bench::AgeRow> ages;
        for (size_t i : detected)
            ages.push_back({rows[i].age, rows[i].ageEvidence, rows[i].shipped.age, rows[i].sex, rows[i].brows.thickness,
                rows[i].brows.contrast});
        report << bench::ageReport(ages);
        report << bench::browReport(ages);
    }
    // Skin lightness.
    std::vector<double> drawn, cheeks, diff;
    for (size_t i : detected) {
        drawn.push_back(rows[i].drawnL);
        cheeks.push_back(rows[i].cheekL);
        diff.push_back(std::abs(rows[i].drawnL - rows[i].cheekL));
    }
    report << QStringLiteral("skin L*: rank correlation %1, median |dL*| %2, p90 %3")
                  .arg(bench::spearman(drawn, cheeks), 0, 'f', 3)
                  .arg(bench::quantile(diff, 0.5), 0, 'f', 1)
                  .arg(bench::quantile(diff, 0.9), 0, 'f', 1);
    // ... and against the labels' skin tone, which no sample of ours decides: the drawn L*'s
    // median per label, its rank correlation with dark < medium < light, and the faces labelled
    // dark drawn lighter than the median face labelled medium (a dark skin drawn pale).
    {
        std::map<QString, std::vector<double>> byTone;
        std::vector<double> order, drawnAll;
        for (size_t i : detected) {
            const int rank = rows[i].skin == QLatin1String("dark") ? 0
                : rows[i].skin == QLatin1String("medium")          ? 1
                : rows[i].skin == QLatin1String("light")           ? 2
                                                                   : -1;
            if (rank < 0)
                continue;
            byTone[rows[i].skin].push_back(rows[i].drawnL);
            order.push_back(rank);
            drawnAll.push_back(rows[i].drawnL);
        }
        const double mediumMedian = bench::quantile(byTone[QStringLiteral("medium")], 0.5);
        const auto paleDark = std::count_if(byTone[QStringLiteral("dark")].begin(),
            byTone[QStringLiteral("dark")].end(), [&](double l) { return l > mediumMedian; });
        report << QStringLiteral("skin L* drawn by label: dark %1 medium %2 light %3 (medians); rank correlation "
                                 "with dark<medium<light %4; labelled dark drawn lighter than the medium median %5/%6")
                      .arg(bench::quantile(byTone[QStringLiteral("dark")], 0.5), 0, 'f', 1)
                      .arg(mediumMedian, 0, 'f', 1)
                      .arg(bench::quantile(byTone[QStringLiteral("light")], 0.5), 0, 'f', 1)
                      .arg(bench::spearman(drawnAll, order), 0, 'f', 3)
                      .arg(paleDark)
                      .arg(byTone[QStringLiteral("dark")].size());
    }
    // Hair colour: the drawn hair's L* by label (where hair is drawn), light hair (blond, grey)
    // drawn light (L* from 40) and dark hair drawn dark, and the rank correlation of L* with
    // black < brown < blond < grey.
    {
        const std::vector<std::pair<QString, double>> kinds {{QStringLiteral("black"), 0}, {QStringLiteral("brown"), 1},
            {QStringLiteral("red"), 1}, {QStringLiteral("blond"), 2}, {QStringLiteral("grey"), 3}};
        std::map<QString, std::vector<double>> byKind;
        std::vector<double> order, lightness;
        int right = 0, counted = 0;
        for (size_t i : detected) {
            const Labelled &r = rows[i];
            if (r.shipped.bald || r.shipped.hat)
                continue;
            for (const auto &[name, rank] : kinds) {
                if (r.hairColour != name)
                    continue;
                const double l = lStar(r.drawnHair);
                byKind[name].push_back(l);
                ++counted;
                right += (rank >= 2) == (l >= 40.0);
                if (name != QLatin1String("red")) {
                    order.push_back(rank);
                    lightness.push_back(l);
                }
            }
        }
        QString medians;
        for (const auto &[name, rank] : kinds)
            medians += QStringLiteral(" %1 %2 (n %3)")
                           .arg(name)
                           .arg(bench::quantile(byKind[name], 0.5), 0, 'f', 1)
                           .arg(byKind[name].size());
        report << QStringLiteral(
            "hair colour: drawn L* median by label:%1; light hair drawn light and dark dark %2/%3; "
            "rank correlation of L* with black<brown<blond<grey %4")
                      .arg(medians)
                      .arg(right)
                      .arg(counted)
                      .arg(bench::spearman(order, lightness), 0, 'f', 3);
    }
    {
        std::vector<bench::HairColourRow> hair;
        for (size_t i : detected)
            hair.push_back(rows[i].hair);
        report << bench::hairColourReport(hair);
    }
    // Which measures are evidence of what: the ROC area of each, per label.
    const std::vector<std::pair<QString, std::function<bool(const Labelled &)>>> labels {
        {QStringLiteral("facialHair"), [](const Labelled &r) { return r.beard || r.moustache || r.goatee; }},
        {QStringLiteral("moustache"), [](const Labelled &r) { return r.moustache; }},
        {QStringLiteral("beard"), [](const Labelled &r) { return r.beard; }},
        {QStringLiteral("goatee"), [](const Labelled &r) { return r.goatee; }},
        {QStringLiteral("glasses"), [](const Labelled &r) { return r.glasses; }},
        {QStringLiteral("headwear"), [](const Labelled &r) { return r.headwear; }},
        {QStringLiteral("bald"), [](const Labelled &r) { return r.bald; }},
        {QStringLiteral("longHair"), [](const Labelled &r) { return r.hairLength == QLatin1String("long"); }}};
    QJsonObject auc;
    for (const auto &[name, truthOf] : labels) {
        std::vector<bool> truth(rows.size());
        for (size_t i = 0; i < rows.size(); ++i)
            truth[i] = truthOf(rows[i]);
        QStringList line;
        for (const auto &[measure, unused] : rows[detected.front()].m) {
            std::vector<double> score(rows.size(), 0.0);
            for (size_t i : detected)
                score[i] = rows[i].m.at(measure);
            line << QStringLiteral("%1 %2")
                        .arg(QString::fromStdString(measure))
                        .arg(bench::rocArea(score, truth, detected), 0, 'f', 2);
        }
        auc.insert(name, line.join(QStringLiteral(", ")));
    }
    // Hair length.
    QJsonArray perFace;
    for (const Labelled &r : rows) {
        QJsonObject o;
        o.insert(QStringLiteral("file"), r.file);
        o.insert(QStringLiteral("hairColour"), r.hairColour);
        o.insert(QStringLiteral("headwear"), r.headwear);
        o.insert(QStringLiteral("skin"), r.skin);
        o.insert(QStringLiteral("age"), r.age);
        o.insert(QStringLiteral("sex"), r.sex);
        if (r.detected) {
            const AgeDecision age = decideAge(r.ageEvidence);
            o.insert(QStringLiteral("ageChild"), age.child);
            o.insert(QStringLiteral("ageElderly"), age.elderly);
            QJsonObject m;
            for (const auto &[key, value] : r.m)
                m.insert(QString::fromStdString(key), value);
            o.insert(QStringLiteral("m"), m);
            o.insert(QStringLiteral("drawnL"), r.drawnL);
            o.insert(QStringLiteral("cheekL"), r.cheekL);
            o.insert(QStringLiteral("drawnHair"), r.drawnHair.name());
            o.insert(QStringLiteral("drawnSkin"), r.drawnSkin.name());
            o.insert(QStringLiteral("parsedHair"), r.parsedHair.isValid() ? r.parsedHair.name() : QString());
            if (r.hair.reading.valid)
                o.insert(QStringLiteral("hairReading"),
                    QJsonArray {r.hair.reading.hair.l, r.hair.reading.hair.a, r.hair.reading.hair.b,
                        r.hair.reading.skin.l, r.hair.reading.kept});
            o.insert(QStringLiteral("beardDrawn"), r.hair.beardDrawn.name());
        }
        perFace.append(o);
    }
    if (qEnvironmentVariableIsSet("TOONFACE_LIKENESS_DUMP")) {
        QFile dump(qEnvironmentVariable("TOONFACE_LIKENESS_DUMP"));
        if (dump.open(QIODevice::WriteOnly))
            dump.write(QJsonDocument(perFace).toJson());
    }
    QJsonObject out;
    out.insert(QStringLiteral("report"), QJsonArray::fromStringList(report));
    out.insert(QStringLiteral("rocArea"), auc);
    return out;
}

} // namespace

TOONFACE_BENCHMARK("likeness.attributes", attributes);
