#include "speech/realfft.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace toonface {

RealFft::RealFft(int size)
    : m_size(size)
    , m_half(size / 2)
{
    if (size < 8 || (size & (size - 1)) != 0)
        throw std::invalid_argument("RealFft: the size must be a power of two of at least 8");
    int bits = 0;
    while ((1 << bits) < m_half)
        ++bits;
    m_reversed.resize(size_t(m_half));
    for (int i = 0; i < m_half; ++i) {
        int r = 0;
        for (int b = 0; b < bits; ++b)
            r |= ((i >> b) & 1) << (bits - 1 - b);
        m_reversed[size_t(i)] = r;
    }
    const double tau = 2 * std::numbers::pi;
    for (int length = 4; length <= m_half; length *= 2) {
        for (int j = 0; j < length / 2; ++j) {
            m_twiddleRe.push_back(float(std::cos(tau * j / length)));
            m_twiddleIm.push_back(float(-std::sin(tau * j / length)));
        }
    }
    m_split.resize(size_t(m_half) + 1);
    for (int k = 0; k <= m_half; ++k)
        m_split[size_t(k)] = std::polar(1.0, -tau * k / m_size);
    m_re.resize(size_t(m_half));
    m_im.resize(size_t(m_half));
}

void RealFft::complexTransform(bool inverse)
{
    float *const re = m_re.data();
    float *const im = m_im.data();
    for (int i = 0; i < m_half; ++i) {
        const int r = m_reversed[size_t(i)];
        if (r > i) {
            std::swap(re[i], re[r]);
            std::swap(im[i], im[r]);
        }
    }
    // Lengths 2 and 4 at once: the factors are 1 and -i (forward) or +i (inverse).
    const float turn = inverse ? 1.0f : -1.0f;
    for (int s = 0; s + 3 < m_half; s += 4) {
        const float r0 = re[s] + re[s + 1], i0 = im[s] + im[s + 1];
        const float r1 = re[s] - re[s + 1], i1 = im[s] - im[s + 1];
        const float r2 = re[s + 2] + re[s + 3], i2 = im[s + 2] + im[s + 3];
        const float d3r = re[s + 2] - re[s + 3], d3i = im[s + 2] - im[s + 3];
        // (d3r + i d3i) times (turn i).
        const float r3 = -turn * d3i, i3 = turn * d3r;
        re[s] = r0 + r2;
        im[s] = i0 + i2;
        re[s + 2] = r0 - r2;
        im[s + 2] = i0 - i2;
        re[s + 1] = r1 + r3;
        im[s + 1] = i1 + i3;
        re[s + 3] = r1 - r3;
        im[s + 3] = i1 - i3;
    }
    // The inverse's factors are the conjugates: the imaginary parts change sign.
    const float sign = inverse ? -1.0f : 1.0f;
    size_t stage = 2; // after the factors of length 4
    for (int length = 8; length <= m_half; stage += size_t(length / 2), length *= 2) {
        const int half = length / 2;
        const float *const wr = m_twiddleRe.data() + stage;
        const float *const wi = m_twiddleIm.data() + stage;
        for (int start = 0; start < m_half; start += length) {
            float *ar = re + start;
            float *ai = im + start;
            float *br = re + start + half;
            float *bi = im + start + half;
            // The two halves never overlap: GCC may run the loop four at a time.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC ivdep
#endif
            for (int j = 0; j < half; ++j) {
                const float cr = wr[j], ci = sign * wi[j];
                const float tr = br[j] * cr - bi[j] * ci;
                const float ti = br[j] * ci + bi[j] * cr;
                br[j] = ar[j] - tr;
                bi[j] = ai[j] - ti;
                ar[j] += tr;
                ai[j] += ti;
            }
        }
    }
}

void RealFft::forward(float *data)
{
    // The even samples as the real parts, the odd as the imaginary parts of a half-size
    // transform; its spectrum then splits into the even and odd samples' spectra.
    for (int j = 0; j < m_half; ++j) {
        m_re[size_t(j)] = data[2 * j];
        m_im[size_t(j)] = data[2 * j + 1];
    }
    complexTransform(false);
    data[0] = float(double(m_re[0]) + m_im[0]);
    data[1] = float(double(m_re[0]) - m_im[0]);
    for (int k = 1; k < m_half; ++k) {
        // even = (Z_k + conj Z_(M-k)) / 2, odd = (Z_k - conj Z_(M-k)) / 2i, X_k = even + w^k odd;
        // written out, as std::complex's product checks for infinities on every call.
        const double ar = m_re[size_t(k)], ai = m_im[size_t(k)];
        const double br = m_re[size_t(m_half - k)], bi = -double(m_im[size_t(m_half - k)]);
        const double er = 0.5 * (ar + br), ei = 0.5 * (ai + bi);
        const double or_ = 0.5 * (ai - bi), oi = -0.5 * (ar - br);
        const double wr = m_split[size_t(k)].real(), wi = m_split[size_t(k)].imag();
        data[2 * k] = float(er + wr * or_ - wi * oi);
        data[2 * k + 1] = float(ei + wr * oi + wi * or_);
    }
}

void RealFft::inverse(float *data)
{
    // The reverse of forward's split: the even and odd samples' spectra, joined into one
    // half-size spectrum whose inverse holds the even samples in its real parts and the odd
    // ones in its imaginary parts: with a = X_k, b = conj X_(M-k), even = a + b,
    // odd = (a - b) conj(w^k), Z_k = even + i odd (X_0 and X_M are real, packed in data[0..1]).
    {
        const double a = data[0], b = data[1];
        m_re[0] = float(a + b);
        m_im[0] = float(a - b);
    }
    for (int k = 1; k < m_half; ++k) {
        const double ar = data[2 * k], ai = data[2 * k + 1];
        const double br = data[2 * (m_half - k)], bi = -double(data[2 * (m_half - k) + 1]);
        const double dr = ar - br, di = ai - bi;
        const double wr = m_split[size_t(k)].real(), wi = -m_split[size_t(k)].imag();
        const double or_ = dr * wr - di * wi, oi = dr * wi + di * wr;
        m_re[size_t(k)] = float(ar + br - oi);
        m_im[size_t(k)] = float(ai + bi + or_);
    }
    complexTransform(true);
    for (int j = 0; j < m_half; ++j) {
        data[2 * j] = m_re[size_t(j)];
        data[2 * j + 1] = m_im[size_t(j)];
    }
}

} // namespace toonface
