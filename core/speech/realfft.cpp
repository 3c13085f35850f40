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
    m_twiddle.resize(size_t(std::max(m_half / 2, 1)));
    for (int k = 0; k < int(m_twiddle.size()); ++k)
        m_twiddle[size_t(k)] = std::polar(1.0, -tau * k / m_half);
    m_split.resize(size_t(m_half) + 1);
    for (int k = 0; k <= m_half; ++k)
        m_split[size_t(k)] = std::polar(1.0, -tau * k / m_size);
    m_work.resize(size_t(m_half));
}

void RealFft::complexTransform(int sign)
{
    auto &a = m_work;
    for (int i = 0; i < m_half; ++i) {
        const int r = m_reversed[size_t(i)];
        if (r > i)
            std::swap(a[size_t(i)], a[size_t(r)]);
    }
    for (int len = 2; len <= m_half; len *= 2) {
        const int step = m_half / len;
        for (int start = 0; start < m_half; start += len) {
            for (int j = 0; j < len / 2; ++j) {
                std::complex<double> w = m_twiddle[size_t(j * step)];
                if (sign > 0)
                    w = std::conj(w);
                const std::complex<double> u = a[size_t(start + j)];
                const std::complex<double> v = a[size_t(start + j + len / 2)] * w;
                a[size_t(start + j)] = u + v;
                a[size_t(start + j + len / 2)] = u - v;
            }
        }
    }
}

void RealFft::forward(float *data)
{
    // The even samples as the real parts, the odd as the imaginary parts of a half-size
    // transform; its spectrum then splits into the even and odd samples' spectra.
    for (int j = 0; j < m_half; ++j)
        m_work[size_t(j)] = {double(data[2 * j]), double(data[2 * j + 1])};
    complexTransform(-1);
    const std::complex<double> z0 = m_work[0];
    data[0] = float(z0.real() + z0.imag());
    data[1] = float(z0.real() - z0.imag());
    for (int k = 1; k < m_half; ++k) {
        const std::complex<double> zk = m_work[size_t(k)];
        const std::complex<double> zm = std::conj(m_work[size_t(m_half - k)]);
        const std::complex<double> even = 0.5 * (zk + zm);
        const std::complex<double> odd = std::complex<double>(0, -0.5) * (zk - zm);
        const std::complex<double> x = even + m_split[size_t(k)] * odd;
        data[2 * k] = float(x.real());
        data[2 * k + 1] = float(x.imag());
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
        const std::complex<double> even = xk + xm;
        const std::complex<double> odd = (xk - xm) * std::conj(m_split[size_t(k)]);
        m_work[size_t(k)] = even + std::complex<double>(0, 1) * odd;
    }
    complexTransform(+1);
    for (int j = 0; j < m_half; ++j) {
        data[2 * j] = float(m_work[size_t(j)].real());
        data[2 * j + 1] = float(m_work[size_t(j)].imag());
    }
}

} // namespace toonface
