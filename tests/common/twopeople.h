#pragma once

// A photo of two people for the tests of several faces: `portrait` beside a copy of itself
// scaled to 85%, on grey. The larger face is the left one, which spans x < portrait.width().

#include <QImage>
#include <QPainter>

namespace toonface::testing {

inline QImage twoPeople(const QImage &portrait)
{
    const QImage smaller = portrait.scaled(portrait.size() * 0.85, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    QImage both(portrait.width() + smaller.width(), portrait.height(), QImage::Format_RGB32);
    both.fill(Qt::gray);
    QPainter p(&both);
    p.drawImage(0, 0, portrait);
    p.drawImage(portrait.width(), 0, smaller);
    p.end();
    return both;
}

} // namespace toonface::testing
