// The speech features' own real FFT (speech/realfft.h): exact against a direct DFT, and the
// same spectra (to float precision) as FFmpeg's av_rdft, which the features used before.
#include "speech/realfft.h"
#include "testmain.h"

#include <QRandomGenerator>
#include <QTest>

extern "C" {
#include <libavcodec/avfft.h>
#include <libavutil/mem.h>
}

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

using namespace toonface;

namespace {

// X_k = sum_j x_j e^(-2 pi i jk / n), k = 0 .. n/2, in double.
std::vector<std::complex<double>> directDft(const std::vector<float> &x)
{
    const int n = int(x.size());
    std::vector<std::complex<double>> out(size_t(n / 2 + 1));
    for (int k = 0; k <= n / 2; ++k) {
        std::complex<double> acc = 0;
        for (int j = 0; j < n; ++j)
            acc += double(x[size_t(j)]) * std::polar(1.0, -2 * M_PI * double(j) * k / n);
        out[size_t(k)] = acc;
    }
    return out;
}

// A frame like the features' frames: a windowed voiced sound with noise, zero-padded.
std::vector<float> speechLikeFrame(int n, QRandomGenerator &random)
{
    std::vector<float> x(size_t(n), 0.0f);
    const int window = n * 400 / 1024;
    const double f0 = 80 + random.bounded(250.0);
    for (int i = 0; i < window; ++i) {
        double v = 0;
        for (int h = 1; h < 12; ++h)
            v += std::sin(2 * M_PI * f0 * h * i / 16000 + h) / h;
        v += 0.05 * (random.generateDouble() - 0.5);
        x[size_t(i)] = float(v * (0.54 - 0.46 * std::cos(2 * M_PI * i / (window - 1))));
    }
    return x;
}

double largestMagnitude(const std::vector<float> &packed)
{
    double m = 0;
    for (const float v : packed)
        m = std::max(m, double(std::abs(v)));
    return m;
}

} // namespace

class TestRealFft : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void matchesDirectDft_data()
    {
        QTest::addColumn<int>("size");
        for (const int n : {8, 16, 64, 1024})
            QTest::newRow(QByteArray::number(n).constData()) << n;
    }

    void matchesDirectDft()
    {
        QFETCH(int, size);
        QRandomGenerator random(size);
        std::vector<float> x(static_cast<size_t>(size));
        for (float &v : x)
            v = float(random.generateDouble() * 2 - 1);
        const auto expected = directDft(x);
        RealFft fft(size);
        std::vector<float> packed = x;
        fft.forward(packed.data());
        const double tolerance = 1e-5 * std::sqrt(double(size));
        QVERIFY(std::abs(packed[0] - expected[0].real()) < tolerance);
        QVERIFY(std::abs(packed[1] - expected[size_t(size / 2)].real()) < tolerance);
        for (int k = 1; k < size / 2; ++k) {
            QVERIFY2(std::abs(packed[size_t(2 * k)] - expected[size_t(k)].real()) < tolerance,
                qPrintable(QString::number(k)));
            QVERIFY2(std::abs(packed[size_t(2 * k + 1)] - expected[size_t(k)].imag()) < tolerance,
                qPrintable(QString::number(k)));
        }
        // The inverse gives n times the samples back.
        fft.inverse(packed.data());
        for (int j = 0; j < size; ++j)
            QVERIFY(std::abs(packed[size_t(j)] / size - x[size_t(j)]) < 1e-5);
    }

    // The power spectrum and the normalized autocorrelation the features take from the
    // transforms agree with FFmpeg's to float precision.
    void agreesWithFfmpeg()
    {
        constexpr int kBits = 10, kSize = 1 << kBits;
        RDFTContext *forward = av_rdft_init(kBits, DFT_R2C);
        RDFTContext *inverse = av_rdft_init(kBits, IDFT_C2R);
        QVERIFY(forward && inverse);
        float *aligned = static_cast<float *>(av_malloc(kSize * sizeof(float)));
        QVERIFY(aligned);
        RealFft fft(kSize);
        QRandomGenerator random(7);
        double worstPower = 0, worstAutocorrelation = 0;
        for (int frame = 0; frame < 50; ++frame) {
            const std::vector<float> x = speechLikeFrame(kSize, random);
            // FFmpeg's transforms want their buffer aligned as av_malloc aligns.
            std::vector<float> ours = x, theirs = x;
            fft.forward(ours.data());
            std::copy(theirs.begin(), theirs.end(), aligned);
            av_rdft_calc(forward, aligned);
            std::copy(aligned, aligned + kSize, theirs.begin());
            const double scale = largestMagnitude(theirs);
            QVERIFY(scale > 0);
            // Power per bin (the sign convention of the imaginary parts may differ).
            std::vector<float> powerOurs(kSize / 2 + 1), powerTheirs(kSize / 2 + 1);
            auto power = [](const std::vector<float> &z, std::vector<float> &p) {
                p[0] = z[0] * z[0];
                p[kSize / 2] = z[1] * z[1];
                for (int k = 1; k < kSize / 2; ++k)
                    p[size_t(k)] = z[size_t(2 * k)] * z[size_t(2 * k)] + z[size_t(2 * k + 1)] * z[size_t(2 * k + 1)];
            };
            power(ours, powerOurs);
            power(theirs, powerTheirs);
            for (int k = 0; k <= kSize / 2; ++k)
                worstPower = std::max(
                    worstPower, std::abs(double(powerOurs[size_t(k)]) - powerTheirs[size_t(k)]) / (scale * scale));
            // The autocorrelation: the inverse of the power spectrum, relative to lag 0.
            auto pack = [](const std::vector<float> &p, std::vector<float> &z) {
                z[0] = p[0];
                z[1] = p[kSize / 2];
                for (int k = 1; k < kSize / 2; ++k) {
                    z[size_t(2 * k)] = p[size_t(k)];
                    z[size_t(2 * k + 1)] = 0;
                }
            };
            pack(powerOurs, ours);
            pack(powerTheirs, theirs);
            fft.inverse(ours.data());
            std::copy(theirs.begin(), theirs.end(), aligned);
            av_rdft_calc(inverse, aligned);
            std::copy(aligned, aligned + kSize, theirs.begin());
            QVERIFY(ours[0] > 0 && theirs[0] > 0);
            for (int lag = 0; lag < kSize / 2; ++lag)
                worstAutocorrelation = std::max(worstAutocorrelation,
                    std::abs(double(ours[size_t(lag)]) / ours[0] - double(theirs[size_t(lag)]) / theirs[0]));
        }
        av_rdft_end(forward);
        av_rdft_end(inverse);
        av_free(aligned);
        QVERIFY2(worstPower < 1e-6, qPrintable(QString::number(worstPower)));
        QVERIFY2(worstAutocorrelation < 1e-5, qPrintable(QString::number(worstAutocorrelation)));
    }

    void refusesOtherSizes()
    {
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RealFft(1000));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RealFft(4));
    }
};

TOONFACE_TEST_GUILESS_MAIN(TestRealFft)
#include "tst_realfft.moc"
