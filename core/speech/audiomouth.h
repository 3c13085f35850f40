#pragma once

#include "anim/timeline.h"
#include "face/mouthshape.h"
#include "speech/audio.h"

#include <QVector>

namespace toonface {

struct AudioMouthOptions
{
    double hopMs = 20; // one mouth value per hop
    // Rumble, breath pops and hum under this frequency are filtered out first (second order).
    double highPassHz = 100;
    // Openness follows the level up fast and falls back slower, as lips do.
    double attackMs = 25;
    double releaseMs = 90;
    // The noise floor follows the quietest level (averaged over levelAverageMs) of the last
    // floorWindowS seconds: down at once, up by at most floorRiseDbPerS. A steady background
    // (a fan, a hum) sinks under it within seconds; speech, with its dips between syllables,
    // stays above it through long sentences.
    double floorWindowS = 2.0;
    double floorRiseDbPerS = 3.0;
    double levelAverageMs = 100;
    // The loudest level seen decays by peakDecayDbPerS (toward the floor), so that openness
    // fits the voice's range whatever the microphone's gain.
    double peakDecayDbPerS = 2.0;
    // Until louder sound is heard, the peak is taken as a voice at this level (dBFS): a click
    // in the first silence is not mistaken for the whole range of the voice.
    double initialPeakDb = -30.0;
    double openAboveFloorDb = 12.0; // quieter than floor + this: closed
    double minimumRangeDb = 18.0; // openness 1 is at least this far above the opening level
    // (openness is the amplitude between the opening level's and the peak's)
    double absoluteGateDb = -60.0; // quieter than this (dBFS) is silence, whatever the floor
    double closedBelow = 0.12; // smoothed openness under this: the `m` shape
    double largeFrom = 0.5; // openness from which the large shape of a colour is chosen
    // Brightness (the sound's mean frequency) against its running (geometric) average over the
    // hops loud and dark enough to be vowels (raw openness from vowelFrom, brightness under
    // vowelBrightnessBelowHz: hiss and fricatives left out):
    // under darkBelow times the average rounds the lips (u, o), over brightAbove spreads them (i).
    double darkBelow = 0.85;
    double brightAbove = 1.2;
    double brightnessAverageS = 3.0;
    double vowelFrom = 0.3;
    double vowelBrightnessBelowHz = 2500;
    // A new shape must win this many hops in a row (no flicker between two shapes).
    int holdHops = 2;
};

// One hop's mouth.
struct AudioMouthFrame
{
    double time = 0; // seconds, the hop's end, from the first sample pushed
    MouthShape shape = MouthShape::M;
    double weight = 0; // how far toward `shape` from the shut mouth, 0..1
    double openness = 0; // smoothed, 0..1
    double levelDb = -120; // the hop's RMS level, dBFS
    double floorDb = -120; // the noise floor then
    double brightnessHz = 0; // the hop's mean frequency (RMS of the spectrum's frequency)
};

// The microphone drives the mouth: sound in, one of the nine mouth shapes and a weight out.
//
// Each hop's loudness (RMS, dBFS, after a high-pass that removes rumble) is placed between an adaptive noise floor (the
// quietest recent level) and a decaying peak: that gives the mouth's openness, smoothed with an attack and a release.
// The colour of the sound picks the lips: its mean frequency (from the ratio of the first difference's energy to the
// signal's, i.e. the RMS frequency of its spectrum) against its own running average tells dark (rounded: u, o), mid (e,
// a) and bright (spread: i, e) sounds; openness picks the small or the large shape of each. Quiet is `m`, the lips
// shut.
//
// Works live, chunk by chunk of any size (push()), and on a whole recording (audioMouthTrack()).
// Not thread-safe: one feeder.
class AudioMouth
{
public:
    explicit AudioMouth(int sampleRate = kSpeechSampleRate, AudioMouthOptions options = {});

    // Analyses `count` more samples (mono, [-1, 1]); returns the hops they completed.
    QVector<AudioMouthFrame> push(const float *samples, qsizetype count);
    QVector<AudioMouthFrame> push(const QVector<float> &samples) { return push(samples.constData(), samples.size()); }
    // The last hop's mouth (closed before the first).
    const AudioMouthFrame &current() const { return m_current; }
    // Forgets everything pushed (the floor, the peak, the smoothing).
    void reset();

    int sampleRate() const { return m_rate; }
    const AudioMouthOptions &options() const { return m_options; }

private:
    AudioMouthFrame analyse(double sumSquares, double sumDiffSquares, int count);

    int m_rate;
    AudioMouthOptions m_options;
    int m_hop;
    // The hop being filled.
    double m_sumSquares = 0;
    double m_sumDiffSquares = 0;
    int m_filled = 0;
    float m_previous = 0;
    // The high-pass biquad: coefficients and state.
    double m_b0 = 1, m_b1 = 0, m_b2 = 0, m_a1 = 0, m_a2 = 0;
    double m_x1 = 0, m_x2 = 0, m_y1 = 0, m_y2 = 0;
    qint64 m_hops = 0;
    // Adaptive state.
    bool m_started = false;
    QVector<double> m_recentPower; // the last hops' mean squares (levelAverageMs)
    QVector<double> m_averages; // the averaged levels of the floor's window, dB, oldest first
    bool m_haveAverage = false;
    double m_floorDb = -120;
    double m_peakDb = -120;
    double m_openness = 0;
    double m_averageBrightness = 0;
    MouthShape m_candidate = MouthShape::M;
    int m_candidateHops = 0;
    AudioMouthFrame m_current;
};

// The mouth of a whole recording, one frame per hop.
QVector<AudioMouthFrame> audioMouthTrack(const Audio &audio, const AudioMouthOptions &options = {});

// Mouth keys from hops (one per change of shape, weight the openness it reached), `offset`
// seconds added to the times: for recording the microphone's mouth onto a timeline.
QVector<MouthKey> audioMouthKeys(const QVector<AudioMouthFrame> &frames, double offset = 0.0);

} // namespace toonface
