#include "export/svgnumbers.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace toonface::smil {

void parseNumbers(QByteArrayView text, QVector<double> *numbers, QByteArray *letters)
{
    const char *p = text.data();
    const char *end = p + text.size();
    while (p < end) {
        const char c = *p;
        if ((c >= '0' && c <= '9') || c == '-' || c == '.' || c == '+') {
            double v = 0;
            const char *from = c == '+' ? p + 1 : p;
            const auto [next, ec] = std::from_chars(from, end, v);
            if (ec == std::errc() && next > from) {
                numbers->append(v);
                p = next;
                continue;
            }
        } else if (letters && ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'))) {
            letters->append(c);
        }
        ++p;
    }
}

int pathArity(char command)
{
    switch (command | 0x20) { // lower case
    case 'm':
    case 'l':
    case 't': return 2;
    case 'h':
    case 'v': return 1;
    case 'c': return 6;
    case 's':
    case 'q': return 4;
    case 'a': return 7;
    default: return 0;
    }
}

bool parsePath(QByteArrayView d, QVector<double> *numbers, QByteArray *commands)
{
    const char *p = d.data();
    const char *end = p + d.size();
    char current = 0;
    int pending = 0; // numbers still owed to the current command
    while (p < end) {
        const char c = *p;
        if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z')) {
            if (pending != 0 || (pathArity(c) == 0 && (c | 0x20) != 'z'))
                return false;
            current = c;
            commands->append(c);
            pending = pathArity(c);
            ++p;
            continue;
        }
        if ((c >= '0' && c <= '9') || c == '-' || c == '.' || c == '+') {
            double v = 0;
            const char *from = c == '+' ? p + 1 : p;
            const auto [next, ec] = std::from_chars(from, end, v);
            if (ec != std::errc() || next == from)
                return false;
            if (pending == 0) {
                // An implicit repetition of the current command.
                if (current == 0 || pathArity(current) == 0)
                    return false;
                current = current == 'M' ? 'L' : current == 'm' ? 'l' : current;
                commands->append(current);
                pending = pathArity(current);
            }
            numbers->append(v);
            --pending;
            p = next;
            continue;
        }
        ++p; // separators
    }
    return pending == 0;
}

void appendFixed(QByteArray &out, qint64 n, int decimals)
{
    char buf[32];
    int len = 0;
    if (n < 0) {
        out += '-';
        n = -n;
    }
    const qint64 scale = kPow10[decimals];
    qint64 whole = n / scale;
    qint64 frac = n % scale;
    if (whole != 0 || frac == 0) {
        do {
            buf[len++] = char('0' + whole % 10);
            whole /= 10;
        } while (whole > 0);
        while (len > 0)
            out += buf[--len];
    }
    if (frac != 0) {
        int digits = decimals;
        while (frac % 10 == 0) {
            frac /= 10;
            --digits;
        }
        out += '.';
        for (int i = digits - 1; i >= 0; --i) {
            buf[i] = char('0' + frac % 10);
            frac /= 10;
        }
        out.append(buf, digits);
    }
}

qint64 quantize(double v, int decimals)
{
    if (!std::isfinite(v))
        return 0;
    return std::llround(std::clamp(v, -1e9, 1e9) * double(kPow10[decimals]));
}

QByteArray seconds(double s)
{
    QByteArray out;
    appendFixed(out, quantize(s, 6), 6);
    if (out.startsWith('.'))
        out.prepend('0');
    out += 's';
    return out;
}

namespace {

// Numbers joined as tightly as SVG path grammar allows: no separator before a minus sign, nor
// before a leading point after a number that already has one.
class PathWriter
{
public:
    explicit PathWriter(QByteArray &out)
        : m_out(out)
    { }
    void command(char c)
    {
        m_out += c;
        m_needSeparator = false;
    }
    void number(qint64 n, int decimals)
    {
        const qsizetype at = m_out.size();
        appendFixed(m_out, n, decimals);
        const char first = m_out.at(at);
        const bool joined = first == '-' || (first == '.' && m_lastHasPoint);
        if (m_needSeparator && !joined)
            m_out.insert(at, ' ');
        m_lastHasPoint = m_out.indexOf('.', at) >= 0;
        m_needSeparator = true;
    }

private:
    QByteArray &m_out;
    bool m_needSeparator = false;
    bool m_lastHasPoint = false;
};

} // namespace

void appendRelativePath(QByteArray &out, const QByteArray &commands, const qint64 *v, int decimals)
{
    PathWriter w(out);
    qint64 cx = 0, cy = 0, sx = 0, sy = 0;
    qsizetype i = 0;
    for (qsizetype k = 0; k < commands.size(); ++k) {
        const char c = commands[k];
        switch (c) {
        case 'M':
            if (k == 0) {
                w.command('M');
                w.number(v[i], decimals);
                w.number(v[i + 1], decimals);
            } else {
                w.command('m');
                w.number(v[i] - cx, decimals);
                w.number(v[i + 1] - cy, decimals);
            }
            cx = sx = v[i];
            cy = sy = v[i + 1];
            i += 2;
            break;
        case 'L':
            w.command('l');
            w.number(v[i] - cx, decimals);
            w.number(v[i + 1] - cy, decimals);
            cx = v[i];
            cy = v[i + 1];
            i += 2;
            break;
        case 'C':
            w.command('c');
            for (int j = 0; j < 3; ++j) {
                w.number(v[i + 2 * j] - cx, decimals);
                w.number(v[i + 2 * j + 1] - cy, decimals);
            }
            cx = v[i + 4];
            cy = v[i + 5];
            i += 6;
            break;
        case 'H':
            w.command('h');
            w.number(v[i] - cx, decimals);
            cx = v[i];
            i += 1;
            break;
        case 'V':
            w.command('v');
            w.number(v[i] - cy, decimals);
            cy = v[i];
            i += 1;
            break;
        default: // Z
            w.command('z');
            cx = sx;
            cy = sy;
            break;
        }
    }
}

void appendAbsolutePath(QByteArray &out, const QByteArray &commands, const qint64 *v, int decimals)
{
    PathWriter w(out);
    qsizetype i = 0;
    char last = 0;
    for (const char c : commands) {
        // A command repeated is implied by its numbers (but numbers after M are L's).
        if (c != last || c == 'M' || pathArity(c) == 0)
            w.command(c);
        last = c;
        for (int j = pathArity(c); j > 0; --j)
            w.number(v[i++], decimals);
    }
}

bool relativeWritable(const QByteArray &commands)
{
    return !commands.isEmpty() && commands[0] == 'M'
        && std::all_of(commands.begin(), commands.end(), [](char c) { return QByteArrayView("MLCHVZ").contains(c); });
}

} // namespace toonface::smil
