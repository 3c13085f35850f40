<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>toonface::ApplyDetection</name>
    <message numerus="yes">
        <source>%n faces found: using the one you chose (%1, %2 ms).</source>
        <translation>
            <numerusform>%n face found: using the one you chose (%1, %2 ms).</numerusform>
            <numerusform>%n faces found: using the one you chose (%1, %2 ms).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n faces found: using the largest, most central one (%1, %2 ms). Click another face&apos;s box to switch.</source>
        <translation>
            <numerusform>%n face found: using it (%1, %2 ms).</numerusform>
            <numerusform>%n faces found: using the largest, most central one (%1, %2 ms). Click another face&apos;s box to switch.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>toonface::BlinksDialog</name>
    <message numerus="yes">
        <source>%n blink(s) from %1 s to %2 s.</source>
        <translation>
            <numerusform>%n blink from %1 s to %2 s.</numerusform>
            <numerusform>%n blinks from %1 s to %2 s.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The %n blink(s) there now are replaced.</source>
        <translation>
            <numerusform>The blink there now is replaced.</numerusform>
            <numerusform>The %n blinks there now are replaced.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>toonface::BookDialog</name>
    <message numerus="yes">
        <source>Wrote %1: %n page(s)</source>
        <translation>
            <numerusform>Wrote %1: %n page</numerusform>
            <numerusform>Wrote %1: %n pages</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The project&apos;s audio track (%n recording(s), mixed)</source>
        <translation>
            <numerusform>The project&apos;s audio track (%n recording, mixed)</numerusform>
            <numerusform>The project&apos;s audio track (%n recordings, mixed)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>toonface::ExportAnimationDialog</name>
    <message numerus="yes">
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n frame</numerusform>
            <numerusform>%n frames</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>toonface::ImportVideoDialog</name>
    <message numerus="yes">
        <source>%n frame(s)</source>
        <translation>
            <numerusform>%n frame</numerusform>
            <numerusform>%n frames</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>toonface::LipSyncDialog</name>
    <message numerus="yes">
        <source>%n word(s) in English</source>
        <translation>
            <numerusform>%n word in English</numerusform>
            <numerusform>%n words in English</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n syllable(s) in Mandarin</source>
        <translation>
            <numerusform>%n syllable in Mandarin</numerusform>
            <numerusform>%n syllables in Mandarin</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>toonface::Questions</name>
    <message numerus="yes">
        <source>You moved %n point(s) by hand. Re-detecting replaces every point.</source>
        <translation>
            <numerusform>You moved %n point by hand. Re-detecting replaces every point.</numerusform>
            <numerusform>You moved %n points by hand. Re-detecting replaces every point.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>toonface::Script</name>
    <message numerus="yes">
        <source>%1 (and %n more)</source>
        <translation>
            <numerusform>%1 (and one more)</numerusform>
            <numerusform>%1 (and %n more)</numerusform>
        </translation>
    </message>
</context>
</TS>
