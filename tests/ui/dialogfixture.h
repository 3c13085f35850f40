#pragma once

#include "dialogs/lipsyncdialog.h"
#include "document/document.h"
#include "shareddata.h"
#include "speech/audio.h"

#include <QAbstractButton>
#include <QDir>
#include <QFileInfo>
#include <QPlainTextEdit>
#include <QSignalSpy>
#include <QString>
#include <QTest>
#include <QWidget>

#include <cmath>

// What the dialog tests share: the research recording, made-up sounds, clicking a dialog's
// buttons and looking at a dialog.
namespace toonface::dialogfixture {

inline QString sharedData()
{
    return testing::sharedDataDir();
}

// The Mandarin recording with its script, or empty when the research data is absent.
inline QString realRecording()
{
    const QString path = QDir(sharedData()).filePath(QStringLiteral("speech/SSB00050015_16k.wav"));
    return QFileInfo::exists(path) ? QFileInfo(path).absoluteFilePath() : QString();
}
inline const QString kRealScript = QStringLiteral("经广州日报报道后成为了社会热点");

// A steady tone: sound, but no speech.
inline QString writeTone(const QString &path, double seconds)
{
    Audio audio;
    const int n = int(seconds * audio.sampleRate);
    audio.samples.resize(n);
    for (int i = 0; i < n; ++i)
        audio.samples[i] = float(0.4 * std::sin(2 * M_PI * 440.0 * i / audio.sampleRate));
    QString error;
    return writeAudio(path, audio, &error) ? path : QString();
}

// Clicks the child button with this object name, as a user would.
inline bool click(QWidget *parent, const char *name)
{
    auto *button = parent->findChild<QAbstractButton *>(QString::fromLatin1(name));
    if (!button || !button->isEnabled() || !button->isVisible())
        return false;
    QTest::mouseClick(button, Qt::LeftButton);
    return true;
}

// Puts `script` into the Lip Sync dialog's script box and waits until the dialog has checked
// it (a moment after typing stops, once the dictionary has loaded): on the check itself, not
// on a time, which a loaded machine overran.
inline bool typeScript(LipSyncDialog *dialog, const QString &script)
{
    auto *text = dialog->findChild<QPlainTextEdit *>(QStringLiteral("script"));
    if (!text)
        return false;
    text->selectAll();
    QTest::keyClick(text, Qt::Key_Delete);
    QSignalSpy checked(dialog, &LipSyncDialog::scriptChecked);
    text->insertPlainText(script);
    return checked.wait(60000);
}

// Saves the dialog as a PNG when TOONFACE_GRAB_DIR is set (to look at it).
inline void grab(QWidget *widget, const QString &name)
{
    const QString dir = qEnvironmentVariable("TOONFACE_GRAB_DIR");
    if (!dir.isEmpty())
        widget->grab().save(QDir(dir).filePath(name + QStringLiteral(".png")));
}

} // namespace toonface::dialogfixture
