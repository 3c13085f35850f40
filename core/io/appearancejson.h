#pragma once

#include <QJsonObject>

namespace toonface {

struct AppearanceFindings;
struct Style;

// The face JSON's "appearance" object (architecture.md's contract for `toonface-cli detect`):
// {skin: "#rrggbb", hair: "#rrggbb" or null (none: bald), hairLength: "none"|"short"|"medium"|"long",
//  bald, headwear, moustache, beard, goatee: booleans, glasses: "none"|"round"|"rectangular"|"rimless",
//  confidence: {hairLength, bald, headwear, moustache, beard, goatee, glasses: 0..1}}.
// `style` is the one sampleColours() (detect/photocolours.h) set from the photo (its colours and appearance), and
// `findings` what that found.
QJsonObject appearanceToJson(const Style &style, const AppearanceFindings &findings);

} // namespace toonface
