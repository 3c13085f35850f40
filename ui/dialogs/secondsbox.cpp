#include "dialogs/secondsbox.h"

namespace toonface {

SecondsBox::SecondsBox(QWidget *parent, double maximum)
    : QDoubleSpinBox(parent)
{
    setRange(0, maximum);
    setDecimals(2);
    setSingleStep(0.1);
    setSuffix(tr(" s"));
    setAccelerated(true);
}

} // namespace toonface
