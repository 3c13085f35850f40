#pragma once

#include <complex>
#include <vector>

namespace toonface {

// A real discrete Fourier transform of a power-of-two size (at least 8), forward and inverse,
// in float with the split done in double: speech features need it for a few hundred points a frame,
// and having it here keeps the speech path free of a media library.
//
// The spectrum of n real samples is packed into n floats: X0, X(n/2) (both real), then
// Re X1, Im X1, ..., Re X(n/2-1), Im X(n/2-1), with X_k = sum_j x_j e^(-2 pi i jk / n).
// One object holds its tables and its work buffer: use one per thread.
class RealFft
{
public:
    explicit RealFft(int size);

    int size() const { return m_size; }
    // Transforms `data` (size() samples) in place into the packed spectrum.
    void forward(float *data);
    // The inverse: `data` holds a packed spectrum; it becomes the real sequence
    // x_j = sum_k X_k e^(2 pi i jk / n) over the whole (Hermitian) spectrum, unscaled
    // (n times the usual inverse).
    void inverse(float *data);

private:
    // In-place complex transform of the m_half points in m_re/m_im, forward (e^-) or inverse
    // (e^+, unscaled).
    void complexTransform(bool inverse);

    int m_size = 0;
    int m_half = 0;
    std::vector<int> m_reversed; // bit-reversed index of each of the m_half points
    // The butterflies' factors stage by stage (lengths 4, 8, ..., m_half): for a stage of
    // length L, e^(-2 pi i j / L) for j < L / 2, one stage after the other.
    std::vector<float> m_twiddleRe, m_twiddleIm;
    std::vector<std::complex<double>> m_split; // e^(-2 pi i k / m_size), k <= m_half
    // The work of the complex transform, in float like its input and output: four butterflies
    // per SSE instruction (the split into the real spectrum is done in double).
    std::vector<float> m_re, m_im;
};

} // namespace toonface
