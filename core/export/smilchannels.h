#pragma once

#include "anim/timeline.h"
#include "render/svgface.h"

#include <QByteArray>
#include <QRectF>
#include <QString>
#include <QVector>

namespace toonface {
class MouthShapeSet;
class TimelineEvaluator;
struct HeadPose;
} // namespace toonface

// What moves in an animated drawing: the attributes the SMIL export animates ("channels"),
// which tracks move each of them, and their numbers at any time.
namespace toonface::smil {

enum class ChannelKind { Path, Points, Number, Translate, Rotate, Scale };

// One animated attribute: the geometry attribute of a part, or one transform of the head.
struct Channel
{
    ChannelKind kind = ChannelKind::Number;
    int part = -1; // index into SvgFace::parts(); -1 for the head
    QString attribute; // the geometry attribute ("d", "cx", "points") for parts
    QByteArray commands; // Path: one letter per command
    // Parts: the numbers of the attribute as written in the document (at time 0). Their
    // animations are additive: values are offsets from these, so numbers that never move are
    // written as 0.
    QVector<double> base;
    int size = 0; // numbers
    int decimals = 1; // written to 10^-decimals
    // Values are multiples of `grain` units of 10^-decimals: 2 on a part drawn in fifths of a
    // pixel, whose values are written as whole fifths (smilscale.h).
    int grain = 1;
    double weight = 1; // pixels per unit of its numbers
    Tracks tracks;
};

// Reads the numbers of channel `c` from one drawing into out[0 .. c.size).
bool readChannel(const Channel &c, const QVector<FacePart> &parts, const QVector<double> &head, double *out);
// Reads the numbers of a part channel from its attribute's text into out[0 .. c.size).
bool readChannelText(const Channel &c, QByteArrayView text, double *out);

// The transform of <g id="head">: translate(x,y) rotate(a) scale(s) translate(-cx,-cy).
bool headNumbers(const SvgFace &svg, const HeadPose &head, QVector<double> *out);

// Samples the timeline's drawing: the numbers of chosen channels at a time.
class Sampler
{
public:
    // `parts`: the drawing at time 0, whose structure every sample must have.
    Sampler(const SvgFace &svg, const TimelineEvaluator &evaluator, const QVector<Channel> &channels,
        const QVector<FacePart> &parts);

    // The numbers of channels `which` at time t, one after another. False when the drawing's
    // structure differs from the one at time 0.
    bool sample(double t, const QVector<int> &which, double *out) const;

private:
    const SvgFace &m_svg;
    const TimelineEvaluator &m_evaluator;
    const QVector<Channel> &m_channels;
    const QVector<FacePart> &m_parts;
    qsizetype m_still; // parts that never move: read from m_parts
    qsizetype m_posed; // parts that move: read from SvgFace::posedGeometry()
    QVector<QByteArray> m_ids; // of m_parts
    // Per channel of a moving part, the index of its attribute in the part's posedGeometry()
    // attributes (-1 for the head and the still parts).
    QVector<int> m_attribute;
};

// The channels of a drawing: every numeric geometry attribute of every part, and the head.
QVector<Channel> makeChannels(const QVector<FacePart> &parts, const QVector<double> &neutralHead, QRectF canvas);

// Which tracks move each part channel, found by drawing probe poses of every track the
// timeline uses, on the neutral face and on one pose of every other track (so a dependency
// that shows only in combination, say an eyeball reaching past a shut lid, is found too).
void findTracks(QVector<Channel> &channels, const SvgFace &svg, const Timeline &timeline, const MouthShapeSet &shapes);

// The numbers of a channel's value (quantized, channel size of them) as attribute text.
void appendValue(QByteArray &out, const Channel &c, const qint64 *v);

} // namespace toonface::smil
