#pragma once

// Made-up photos that the tests of several folders share.

#include <QImage>
#include <QPainter>

namespace toonface::testing {

// A photo of two people for the tests of several faces: `portrait` beside a copy of itself
// scaled to 85%, on grey. The larger face is the left one, which spans x < portrait.width().
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

// Two dark blobs on a plain blue wall, 480 x 480: an eye pair by their size, shape and
// spacing, with no face around them.
inline QImage darkPairOnAWall()
{
    QImage wall(480, 480, QImage::Format_RGB32);
    wall.fill(QColor(120, 150, 200));
    QPainter p(&wall);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(20, 20, 30));
    p.drawEllipse(QPointF(190, 200), 14, 8);
    p.drawEllipse(QPointF(290, 200), 14, 8);
    p.end();
    return wall;
}

} // namespace toonface::testing
