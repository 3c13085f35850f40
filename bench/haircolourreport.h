#pragma once

// likeness.attributes' hair colour figures: how the hair's strands read (haircolour.h) lie per
// labelled shade, the shade rules' thresholds fitted by 5-fold stratified cross-validation (the
// held-out folds' confusion and the light/dark split), the shade the drawn colour reads as before
// (the parse's plain median, the beard's darker half) and now, and the beard's colour on the
// bearded faces.

#include "crossvalidation.h"

#include "detect/haircolour.h"

#include <QColor>
#include <QString>
#include <QStringList>

#include <array>
#include <functional>
#include <vector>

namespace toonface::bench {

struct HairColourRow
{
    int shade = -1; // the label as a HairShade, -1 when not one of the five
    HairColourReading reading; // the head hair's strands
    QColor skin; // the skin the drawn colours are read against
    bool hairDrawn = false; // hair drawn (not bald, no hat)
    QColor before, drawn; // the hair's colour as the parse's median gives it, and as drawn now
    bool bearded = false; // labelled beard, moustache or goatee, and facial hair drawn
    QColor beardBefore, beardDrawn; // the facial hair's darker half, and as drawn now
};

inline int hairShadeOfLabel(const QString &label)
{
    for (HairShade s : {HairShade::Black, HairShade::Brown, HairShade::Red, HairShade::Blond, HairShade::Grey})
        if (hairShadeName(s) == label)
            return int(s);
    return -1;
}

// A plain colour read as hair of that colour against `skin` (to tell the shade a drawn colour shows).
inline HairColourReading readingOf(const QColor &colour, const QColor &skin)
{
    HairColourReading r;
    r.valid = colour.isValid();
    if (r.valid) {
        r.hair = labOf(colour);
        r.skin = skin.isValid() ? labOf(skin) : LabColour {};
    }
    return r;
}

inline double ruleParam(const HairShadeRules &r, int k)
{
    const std::array<double, 6> v {r.greyChroma, r.greyL, r.redChroma, r.redHue, r.blondL, r.blackL};
    return v[size_t(k)];
}

inline void setRuleParam(HairShadeRules *r, int k, double value)
{
    std::array<double *, 6> v {&r->greyChroma, &r->greyL, &r->redChroma, &r->redHue, &r->blondL, &r->blackL};
    *v[size_t(k)] = value;
}

// The mean of the shades' recalls (each shade counts alike, however few its faces).
inline double balancedAccuracy(const std::array<std::array<int, 5>, 5> &confusion)
{
    double sum = 0;
    int classes = 0;
    for (size_t t = 0; t < confusion.size(); ++t) {
        int n = 0;
        for (int v : confusion[t])
            n += v;
        if (n == 0)
            continue;
        sum += double(confusion[t][t]) / n;
        ++classes;
    }
    return classes > 0 ? sum / classes : 0.0;
}

// The shade rules fitted on `train` for balanced accuracy: each threshold in turn over the
// midpoints of its feature's values (L*, chroma or hue), three rounds from a fixed start.
inline HairShadeRules fitHairShadeRules(const std::vector<HairColourRow> &rows, const std::vector<size_t> &train)
{
    // A start set before looking at any face (plain guesses of where the shades part), so that
    // no fold's fit starts from what the others' faces chose.
    HairShadeRules rules;
    rules.greyChroma = 8;
    rules.greyL = 50;
    rules.redChroma = 20;
    rules.redHue = 55;
    rules.blondL = 55;
    rules.blackL = 25;
    auto score = [&](const HairShadeRules &r) {
        std::array<std::array<int, 5>, 5> c {};
        for (size_t i : train)
            ++c[size_t(rows[i].shade)][size_t(classifyHair(rows[i].reading, r).shade)];
        return balancedAccuracy(c);
    };
    std::array<std::vector<double>, 3> feature; // L*, chroma, hue
    for (size_t i : train) {
        feature[0].push_back(rows[i].reading.hair.l);
        feature[1].push_back(rows[i].reading.chroma());
        feature[2].push_back(rows[i].reading.hue());
    }
    const std::array<int, 6> featureOf {1, 0, 1, 2, 0, 0};
    std::array<std::vector<double>, 3> candidates;
    for (size_t f = 0; f < 3; ++f)
        candidates[f] = thresholdsFrom(feature[f], 60);
    for (int round = 0; round < 3; ++round)
        for (int k = 0; k < 6; ++k) {
            double best = score(rules), bestValue = ruleParam(rules, k);
            for (double v : candidates[size_t(featureOf[size_t(k)])]) {
                HairShadeRules tried = rules;
                setRuleParam(&tried, k, v);
                const double s = score(tried);
                if (s > best + 1e-12) {
                    best = s;
                    bestValue = v;
                }
            }
            setRuleParam(&rules, k, bestValue);
        }
    return rules;
}

inline QStringList confusionLines(const std::array<std::array<int, 5>, 5> &c)
{
    QStringList out;
    int right = 0, n = 0, lightRight = 0;
    for (size_t t = 0; t < 5; ++t)
        for (size_t p = 0; p < 5; ++p) {
            n += c[t][p];
            right += t == p ? c[t][p] : 0;
            // Light (blond, grey) against dark (black, brown, red).
            const bool lightT = t >= size_t(HairShade::Blond), lightP = p >= size_t(HairShade::Blond);
            lightRight += lightT == lightP ? c[t][p] : 0;
        }
    out << QStringLiteral("    right %1 of %2 (%3), balanced %4; light/dark right %5 of %2; rows labelled, columns "
                          "called (black brown red blond grey):")
               .arg(right)
               .arg(n)
               .arg(n > 0 ? double(right) / n : 0.0, 0, 'f', 3)
               .arg(balancedAccuracy(c), 0, 'f', 3)
               .arg(lightRight);
    for (size_t t = 0; t < 5; ++t)
        out << QStringLiteral("    %1 %2 %3 %4 %5 %6")
                   .arg(hairShadeName(HairShade(t)), -6)
                   .arg(c[t][0], 4)
                   .arg(c[t][1], 4)
                   .arg(c[t][2], 4)
                   .arg(c[t][3], 4)
                   .arg(c[t][4], 4);
    return out;
}

inline QStringList hairColourReport(const std::vector<HairColourRow> &rows)
{
    QStringList out;
    std::vector<size_t> scored;
    std::vector<int> label;
    for (size_t i = 0; i < rows.size(); ++i)
        if (rows[i].shade >= 0 && rows[i].reading.valid) {
            scored.push_back(i);
            label.push_back(rows[i].shade);
        }
    // How the strands read, per labelled shade: medians and quartiles of L*, chroma, hue, and L*
    // over the skin's.
    out << QStringLiteral("hair colour — the strands read (haircolour.h), by label: median [quartiles]");
    for (int s = 0; s < 5; ++s) {
        std::vector<double> l, c, h, dl;
        for (size_t i : scored)
            if (rows[i].shade == s) {
                l.push_back(rows[i].reading.hair.l);
                c.push_back(rows[i].reading.chroma());
                h.push_back(rows[i].reading.hue());
                dl.push_back(rows[i].reading.hair.l - rows[i].reading.skin.l);
            }
        auto q = [](const std::vector<double> &v) {
            return QStringLiteral("%1 [%2 %3]")
                .arg(quantile(v, 0.5), 0, 'f', 1)
                .arg(quantile(v, 0.25), 0, 'f', 1)
                .arg(quantile(v, 0.75), 0, 'f', 1);
        };
        if (l.empty())
            continue;
        out << QStringLiteral("  %1 (n %2): L* %3, chroma %4, hue %5, L* over skin %6")
                   .arg(hairShadeName(HairShade(s)))
                   .arg(l.size())
                   .arg(q(l), q(c), q(h), q(dl));
    }
    // The rules fitted on four folds, called on the fifth.
    const int k = 5;
    const std::vector<int> fold = stratifiedFolds(label, k);
    std::array<std::array<int, 5>, 5> heldOut {};
    for (int f = 0; f < k; ++f) {
        std::vector<size_t> train;
        for (size_t j = 0; j < scored.size(); ++j)
            if (fold[j] != f)
                train.push_back(scored[j]);
        const HairShadeRules rules = fitHairShadeRules(rows, train);
        for (size_t j = 0; j < scored.size(); ++j)
            if (fold[j] == f)
                ++heldOut[size_t(label[j])][size_t(classifyHair(rows[scored[j]].reading, rules).shade)];
    }
    const HairShadeRules all = fitHairShadeRules(rows, scored);
    out << QStringLiteral("  shade rules fitted on all %1 faces (balanced accuracy): greyChroma %2 greyL %3 "
                          "redChroma %4 redHue %5 blondL %6 blackL %7")
               .arg(scored.size())
               .arg(all.greyChroma, 0, 'f', 2)
               .arg(all.greyL, 0, 'f', 2)
               .arg(all.redChroma, 0, 'f', 2)
               .arg(all.redHue, 0, 'f', 2)
               .arg(all.blondL, 0, 'f', 2)
               .arg(all.blackL, 0, 'f', 2);
    out << QStringLiteral("  the strands' shade, held out (5-fold stratified):");
    out << confusionLines(heldOut);
    // The shade the drawn colour shows (under the shipped rules), before and now, where hair is drawn.
    auto drawnConfusion = [&](const std::function<QColor(const HairColourRow &)> &colour) {
        std::array<std::array<int, 5>, 5> c {};
        for (size_t i = 0; i < rows.size(); ++i)
            if (rows[i].shade >= 0 && rows[i].hairDrawn && colour(rows[i]).isValid())
                ++c[size_t(rows[i].shade)][size_t(classifyHair(readingOf(colour(rows[i]), rows[i].skin)).shade)];
        return c;
    };
    out << QStringLiteral("  the drawn hair's shade, before (the parse's median where it drew from it):");
    out << confusionLines(drawnConfusion([](const HairColourRow &r) { return r.before; }));
    out << QStringLiteral("  the drawn hair's shade, now:");
    out << confusionLines(drawnConfusion([](const HairColourRow &r) { return r.drawn; }));
    // Facial hair: drawn grey on the bearded faces whose hair is labelled grey, and on the others.
    int greyBefore = 0, greyNow = 0, greyN = 0, otherBefore = 0, otherNow = 0, otherN = 0;
    for (const HairColourRow &r : rows) {
        if (!r.bearded || r.shade < 0)
            continue;
        auto isGrey = [&](const QColor &c) {
            return c.isValid() && classifyHair(readingOf(c, r.skin)).shade == HairShade::Grey;
        };
        const bool greyLabel = r.shade == int(HairShade::Grey);
        (greyLabel ? greyN : otherN)++;
        (greyLabel ? greyBefore : otherBefore) += isGrey(r.beardBefore);
        (greyLabel ? greyNow : otherNow) += isGrey(r.beardDrawn);
    }
    out << QStringLiteral("  facial hair drawn grey: on the %1 bearded faces with grey hair, before %2, now %3; "
                          "on the %4 bearded with other hair, before %5, now %6")
               .arg(greyN)
               .arg(greyBefore)
               .arg(greyNow)
               .arg(otherN)
               .arg(otherBefore)
               .arg(otherNow);
    return out;
}

} // namespace toonface::bench
