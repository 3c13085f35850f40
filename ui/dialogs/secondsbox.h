#pragma once

#include <QDoubleSpinBox>

namespace toonface {

// A time on the timeline, in seconds to the hundredth.
class SecondsBox : public QDoubleSpinBox
{
    Q_OBJECT

public:
    explicit SecondsBox(QWidget *parent = nullptr, double maximum = 24 * 3600);
};

} // namespace toonface
