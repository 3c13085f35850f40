#pragma once

#include <QRegularExpression>
#include <QString>

// The names of a PNG sequence's frames: frame_00001.png, frame_00002.png, ...
namespace toonface {

inline const QRegularExpression &pngFramePattern()
{
    static const QRegularExpression re(QStringLiteral("^frame_(\\d{5,})\\.png$"));
    return re;
}

inline QString pngFrameName(int number)
{
    return QStringLiteral("frame_%1.png").arg(number, 5, 10, QLatin1Char('0'));
}

} // namespace toonface
