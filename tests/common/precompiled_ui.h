// Precompiled for the test suites of the editor (TOONFACE_PCH): those of the engine's suites and
// the Widgets headers the editor's suites include.
#pragma once

#include "precompiled_core.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QUndoStack>
#include <QWidget>
