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
    if (size < 4 || (size & (size - 1)) != 0)
        throw std::invalid_argument("RealFft: the size must be a power of two of at least 4");
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
            m_twiddleRe.push_back(std::cos(tau * j / length));
            m_twiddleIm.push_back(-std::sin(tau * j / length));
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
    double *const re = m_re.data();
    double *const im = m_im.data();
    for (int i = 0; i < m_half; ++i) {
        const int r = m_reversed[size_t(i)];
        if (r > i) {
            std::swap(re[i], re[r]);
            std::swap(im[i], im[r]);
        }
    }
    // Length 2: the factor is 1.
    for (int s = 0; s + 1 < m_half; s += 2) {
        const double ur = re[s], ui = im[s], vr = re[s + 1], vi = im[s + 1];
        re[s] = ur + vr;
        im[s] = ui + vi;
        re[s + 1] = ur - vr;
        im[s + 1] = ui - vi;
    }
    // The inverse's factors are the conjugates: the imaginary parts change sign.
    const double sign = inverse ? -1.0 : 1.0;
    size_t stage = 0;
    for (int length = 4; length <= m_half; stage += size_t(length / 2), length *= 2) {
        const int half = length / 2;
        const double *const wr = m_twiddleRe.data() + stage;
        const double *const wi = m_twiddleIm.data() + stage;
        for (int start = 0; start < m_half; start += length) {
            double *__restrict ar = re + start;
            double *__restrict ai = im + start;
            double *__restrict br = re + start + half;
            double *__restrict bi = im + start + half;
            for (int j = 0; j < half; ++j) {
                const double cr = wr[j], ci = sign * wi[j];
                const double tr = br[j] * cr - bi[j] * ci;
                const double ti = br[j] * ci + bi[j] * cr;
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
        m_re[size_t(j)] = double(data[2 * j]);
        m_im[size_t(j)] = double(data[2 * j + 1]);
    }
    complexTransform(false);
    data[0] = float(m_re[0] + m_im[0]);
    data[1] = float(m_re[0] - m_im[0]);
    for (int k = 1; k < m_half; ++k) {
        // even = (Z_k + conj Z_(M-k)) / 2, odd = (Z_k - conj Z_(M-k)) / 2i, X_k = even + w^k odd;
        // written out, as std::complex's product checks for infinities on every call.
        const double ar = m_re[size_t(k)], ai = m_im[size_t(k)];
        const double br = m_re[size_t(m_half - k)], bi = -m_im[size_t(m_half - k)];
        const double er = 0.5 * (ar + br), ei = 0.5 * (ai + bi);
        const double or_ = 0.5 * (ai - bi), oi = -0.5 * (ar - br);
        const double wr = m_split[size_t(k)].real(), wi = m_split[size_t(k)].imag();
        data[2 * k] = float(er + wr * or_ - wi * oi);
        data[2 * k + 1] = float(ei + wr * oi + wi * or_);
    }
}

void RealFft::inverse(float *data)
{
    auto bin = [&](int k) -> std::complex<double> {
        if (k == 0)
            return {double(data[0]), 0.0};
        if (k == m_half)
            return {double(data[1]), 0.0};
        return {double(data[2 * k]), double(data[2 * k + 1])};
    };
    // The reverse of forward's split: the even and odd samples' spectra, joined into one
    // half-size spectrum whose inverse holds the even samples in its real parts and the odd
    // ones in its imaginary parts.
    for (int k = 0; k < m_half; ++k) {
        const std::complex<double> xk = bin(k);
        const std::complex<double> xm = std::conj(bin(m_half - k));
        // even = X_k + conj X_(M-k), odd = (X_k - conj X_(M-k)) conj(w^k), Z_k = even + i odd.
        const double dr = xk.real() - xm.real(), di = xk.imag() - xm.imag();
        const double wr = m_split[size_t(k)].real(), wi = -m_split[size_t(k)].imag();
        const double or_ = dr * wr - di * wi, oi = dr * wi + di * wr;
        m_re[size_t(k)] = xk.real() + xm.real() - oi;
        m_im[size_t(k)] = xk.imag() + xm.imag() + or_;
    }
    complexTransform(true);
    for (int j = 0; j < m_half; ++j) {
        data[2 * j] = float(m_re[size_t(j)]);
        data[2 * j + 1] = float(m_im[size_t(j)]);
    }
}

} // namespace toonface
