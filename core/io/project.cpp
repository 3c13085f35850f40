#include "io/project.h"

#include "i18n/coretext.h"
#include "io/jsonfield.h"
#include "io/layersjson.h"
#include "io/pointsjson.h"
#include "io/syllablesjson.h"
#include "media/mediareader.h"
#include "media/soundcheck.h"
#include "media/userfile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSaveFile>

#include <limits>

namespace toonface {

namespace {

constexpr const char *kProjectFormat = "toonface.project";
// Far above any real project (a 10-minute timeline is about a megabyte): refuses to pull a
// mistaken multi-gigabyte file into memory.
constexpr qint64 kMaxProjectBytes = 256ll * 1024 * 1024;

constexpr std::array<const char *, 4> kOffsetKeys = {"up", "dn", "lf", "rt"}; // MouthControl order

// The variants a style may name; their spelling is style.h's (eyebrowVariantName, noseVariantName).
constexpr std::array<EyebrowVariant, 3> kEyebrowVariants
    = {EyebrowVariant::Polyline, EyebrowVariant::Bezier, EyebrowVariant::Thick};
constexpr std::array<NoseVariant, 3> kNoseVariants = {NoseVariant::Full, NoseVariant::Simple, NoseVariant::Tip};
constexpr std::array<GlassesShape, 4> kGlassesShapes
    = {GlassesShape::None, GlassesShape::Round, GlassesShape::Rectangular, GlassesShape::Rimless};
constexpr std::array<AgeGroup, 3> kAgeGroups = {AgeGroup::Adult, AgeGroup::Child, AgeGroup::Elderly};

template<typename Enum, std::size_t N>
bool enumFromJson(
    const std::array<Enum, N> &values, QString (*nameOf)(Enum), const JsonField &field, Enum *out, QString *error)
{
    QString s;
    if (!field.toString(&s, error))
        return false;
    QStringList all;
    for (Enum v : values) {
        if (s == nameOf(v)) {
            *out = v;
            return true;
        }
        all << QLatin1Char('"') + nameOf(v) + QLatin1Char('"');
    }
    return field.expected(ProjectText::tr("one of %1").arg(all.join(QStringLiteral(", "))), error);
}

int hexDigit(QChar c)
{
    const char16_t u = c.unicode();
    if (u >= u'0' && u <= u'9')
        return u - u'0';
    if (u >= u'a' && u <= u'f')
        return u - u'a' + 10;
    if (u >= u'A' && u <= u'F')
        return u - u'A' + 10;
    return -1;
}

QString colourToJson(const QColor &c)
{
    if (!c.isValid())
        return QStringLiteral("none");
    return c.name(c.alpha() == 255 ? QColor::HexRgb : QColor::HexArgb);
}

// "#rrggbb", "#aarrggbb", "none" or absent (no colour); nothing else, so that a typo is
// reported rather than read as some other colour.
bool colourFromJson(const JsonField &field, QColor *out, QString *error)
{
    if (field.isMissing()) {
        *out = QColor();
        return true;
    }
    const QString expected = ProjectText::tr("a colour like #rrggbb or #aarrggbb, or \"none\"");
    if (!field.value().isString())
        return field.expected(expected, error);
    const QString s = field.value().toString();
    if (s == QLatin1StringView("none")) {
        *out = QColor();
        return true;
    }
    if (!s.startsWith(QLatin1Char('#')) || (s.size() != 7 && s.size() != 9))
        return field.expected(expected, error);
    uint v = 0;
    for (qsizetype i = 1; i < s.size(); ++i) {
        const int digit = hexDigit(s.at(i));
        if (digit < 0)
            return field.expected(expected, error);
        v = (v << 4) | uint(digit);
    }
    *out = QColor::fromRgba(s.size() == 7 ? (0xff000000u | v) : v);
    return true;
}

QString pathToDisk(const QString &path, const QDir &dir)
{
    return path.isEmpty() ? QString() : dir.relativeFilePath(path);
}

QString pathFromDisk(const QString &path, const QDir &dir)
{
    return path.isEmpty() ? QString() : QDir::cleanPath(dir.absoluteFilePath(path));
}

QJsonObject termToJson(const FapuTerm &t)
{
    QJsonObject o;
    o.insert(QStringLiteral("mns"), t.mns);
    o.insert(QStringLiteral("mw"), t.mw);
    o.insert(QStringLiteral("lowerLip"), t.lowerLip);
    o.insert(QStringLiteral("px"), t.px);
    return o;
}

bool termFromJson(const JsonField &field, FapuTerm *t, QString *error)
{
    QJsonObject unused;
    return field.toObject(&unused, error) && field.member("mns").toNumber(&t->mns, error)
        && field.member("mw").toNumber(&t->mw, error) && field.member("lowerLip").toNumber(&t->lowerLip, error)
        && field.member("px").toNumber(&t->px, error);
}

QJsonObject styleToJson(const Style &style)
{
    QJsonObject s;
    s.insert(QStringLiteral("name"), style.name);
    s.insert(QStringLiteral("cornerCutDepth"), style.cornerCutDepth);
    s.insert(QStringLiteral("cute"), style.cute);
    s.insert(QStringLiteral("eyebrows"), eyebrowVariantName(style.eyebrows));
    s.insert(QStringLiteral("nose"), noseVariantName(style.nose));
    s.insert(QStringLiteral("caricature"), style.caricature);
    QJsonObject look;
    look.insert(QStringLiteral("glasses"), glassesShapeName(style.appearance.glasses));
    look.insert(QStringLiteral("moustache"), style.appearance.moustache);
    look.insert(QStringLiteral("beard"), style.appearance.beard);
    look.insert(QStringLiteral("goatee"), style.appearance.goatee);
    look.insert(QStringLiteral("hat"), style.appearance.hat);
    look.insert(QStringLiteral("wrap"), style.appearance.wrap);
    look.insert(QStringLiteral("bald"), style.appearance.bald);
    look.insert(QStringLiteral("age"), ageGroupName(style.appearance.age));
    if (const GlassesFit &lens = style.appearance.lens; lens.isSet())
        look.insert(QStringLiteral("lens"),
            QJsonObject {{QStringLiteral("halfWidth"), lens.halfWidth}, {QStringLiteral("halfHeight"), lens.halfHeight},
                {QStringLiteral("outward"), lens.outward}, {QStringLiteral("down"), lens.down}});
    s.insert(QStringLiteral("appearance"), look);
    QJsonObject components;
    for (auto it = style.components.cbegin(); it != style.components.cend(); ++it) {
        QJsonObject c;
        c.insert(QStringLiteral("fill"), colourToJson(it->fill));
        c.insert(QStringLiteral("stroke"), colourToJson(it->stroke));
        c.insert(QStringLiteral("strokeWidth"), it->strokeWidth);
        c.insert(QStringLiteral("visible"), it->visible);
        components.insert(it.key(), c);
    }
    s.insert(QStringLiteral("components"), components);
    if (!style.layers.isEmpty())
        s.insert(QStringLiteral("layers"), styleLayersToJson(style.layers));
    return s;
}

bool styleFromJson(const JsonField &field, Style *style, QString *error)
{
    QJsonObject unused;
    if (!field.toObject(&unused, error) || !field.member("name").toString(&style->name, error)
        || !field.member("cornerCutDepth").toInt(0, 8, &style->cornerCutDepth, error)
        || !field.member("cute").toBool(&style->cute, error)
        || !enumFromJson(kEyebrowVariants, &eyebrowVariantName, field.member("eyebrows"), &style->eyebrows, error)
        || !enumFromJson(kNoseVariants, &noseVariantName, field.member("nose"), &style->nose, error))
        return false;
    // Added later: files without them keep their drawing (no exaggeration, nothing worn).
    style->caricature = 0;
    if (const JsonField c = field.member("caricature"); !c.isMissing()) {
        if (!c.toNumber(&style->caricature, error))
            return false;
        if (style->caricature < 0 || style->caricature > kMaxCaricature)
            return c.expected(ProjectText::tr("a number from 0 to %1").arg(kMaxCaricature), error);
    }
    style->appearance = Appearance();
    if (const JsonField look = field.member("appearance"); !look.isMissing()) {
        Appearance &a = style->appearance;
        if (!look.toObject(&unused, error)
            || !enumFromJson(kGlassesShapes, &glassesShapeName, look.member("glasses"), &a.glasses, error)
            || !look.member("moustache").toBool(&a.moustache, error) || !look.member("beard").toBool(&a.beard, error)
            || !look.member("hat").toBool(&a.hat, error) || !look.member("bald").toBool(&a.bald, error))
            return false;
        // Added later: without it, no wrap.
        if (const JsonField wrap = look.member("wrap"); !wrap.isMissing() && !wrap.toBool(&a.wrap, error))
            return false;
        // Added later: without it, no goatee.
        if (const JsonField goatee = look.member("goatee"); !goatee.isMissing() && !goatee.toBool(&a.goatee, error))
            return false;
        // Added later: without it, an adult.
        if (const JsonField age = look.member("age");
            !age.isMissing() && !enumFromJson(kAgeGroups, &ageGroupName, age, &a.age, error))
            return false;
        // Added later: without it the lenses keep the shape's usual proportions.
        if (const JsonField lens = look.member("lens"); !lens.isMissing()) {
            GlassesFit &fit = a.lens;
            if (!lens.toObject(&unused, error) || !lens.member("halfWidth").toNumber(&fit.halfWidth, error)
                || !lens.member("halfHeight").toNumber(&fit.halfHeight, error)
                || !lens.member("outward").toNumber(&fit.outward, error)
                || !lens.member("down").toNumber(&fit.down, error))
                return false;
            if (fit.halfWidth <= 0 || fit.halfWidth > 2 || fit.halfHeight <= 0 || fit.halfHeight > 2)
                return lens.expected(QStringLiteral("lens half sizes above 0 and at most 2 (ES0)"), error);
            if (std::abs(fit.outward) > 2 || std::abs(fit.down) > 2)
                return lens.expected(QStringLiteral("a lens offset of at most 2 (ES0) each way"), error);
        }
    }
    const JsonField components = field.member("components");
    QJsonObject all;
    if (!components.toObject(&all, error))
        return false;
    style->components.clear();
    for (auto it = all.constBegin(); it != all.constEnd(); ++it) {
        const JsonField c = components.member(it.key());
        if (it.key().isEmpty())
            return c.fail(ProjectText::tr("a component needs a name"), error);
        ComponentStyle cs;
        if (!c.toObject(&unused, error) || !colourFromJson(c.member("fill"), &cs.fill, error)
            || !colourFromJson(c.member("stroke"), &cs.stroke, error))
            return false;
        const JsonField width = c.member("strokeWidth");
        if (!width.toNumber(&cs.strokeWidth, error))
            return false;
        if (cs.strokeWidth < 0)
            return width.expected(ProjectText::tr("a width of 0 or more"), error);
        if (!c.member("visible").toBool(&cs.visible, error))
            return false;
        style->components.insert(it.key(), cs);
    }
    return styleLayersFromJson(field.member("layers"), &style->layers, error);
}

QJsonObject mouthShapesToJson(const MouthShapeSet &shapes)
{
    QJsonObject all;
    for (MouthShape shape : kAllMouthShapes) {
        const MouthShapePreset &p = shapes.preset(shape);
        QJsonObject o;
        for (int k = 0; k < 4; ++k) {
            QJsonObject offset;
            offset.insert(QStringLiteral("dx"), termToJson(p.offsets[k].dx));
            offset.insert(QStringLiteral("dy"), termToJson(p.offsets[k].dy));
            o.insert(QLatin1StringView(kOffsetKeys[k]), offset);
        }
        o.insert(QStringLiteral("cornersAtLipMiddle"), p.cornersAtLipMiddle);
        o.insert(QStringLiteral("cornersFromPrevious"), p.cornersFromPrevious);
        all.insert(mouthShapeName(shape), o);
    }
    return all;
}

bool mouthShapesFromJson(const JsonField &field, MouthShapeSet *shapes, QString *error)
{
    QJsonObject all;
    if (!field.toObject(&all, error))
        return false;
    // Unknown names first: a misspelt shape is better reported as such than as a missing one.
    for (auto it = all.constBegin(); it != all.constEnd(); ++it) {
        if (!mouthShapeFromName(it.key())) {
            QStringList names;
            for (MouthShape s : kAllMouthShapes)
                names << mouthShapeName(s);
            return field.member(it.key()).fail(
                ProjectText::tr("unknown mouth shape (the shapes are %1)").arg(names.join(QStringLiteral(", "))),
                error);
        }
    }
    for (MouthShape shape : kAllMouthShapes) {
        const JsonField s = field.member(mouthShapeName(shape));
        QJsonObject unused;
        if (!s.toObject(&unused, error))
            return false;
        MouthShapePreset p;
        for (int k = 0; k < 4; ++k) {
            const JsonField offset = s.member(kOffsetKeys[k]);
            if (!offset.toObject(&unused, error) || !termFromJson(offset.member("dx"), &p.offsets[k].dx, error)
                || !termFromJson(offset.member("dy"), &p.offsets[k].dy, error))
                return false;
        }
        if (!s.member("cornersAtLipMiddle").toBool(&p.cornersAtLipMiddle, error)
            || !s.member("cornersFromPrevious").toBool(&p.cornersFromPrevious, error))
            return false;
        shapes->setPreset(shape, p);
    }
    return true;
}

QString withFile(const QString &path, const QString &message)
{
    return withProblem(QDir::toNativeSeparators(path), message);
}

} // namespace

QJsonObject projectToJson(const Project &project, const QString &projectDir)
{
    const QDir dir(projectDir);
    QJsonObject json;
    json.insert(QStringLiteral("format"), QLatin1StringView(kProjectFormat));
    json.insert(QStringLiteral("version"), kProjectVersion);
    json.insert(QStringLiteral("photo"), pathToDisk(project.photoPath, dir));
    const QSize size = project.face.imageSize();
    if (size.isValid()) {
        QJsonObject s;
        s.insert(QStringLiteral("width"), size.width());
        s.insert(QStringLiteral("height"), size.height());
        json.insert(QStringLiteral("imageSize"), s);
    }
    json.insert(QStringLiteral("points"), pointsToJson(project.face, false));
    json.insert(QStringLiteral("style"), styleToJson(project.style));
    json.insert(QStringLiteral("mouthShapes"), mouthShapesToJson(project.mouthShapes));
    QJsonArray layers;
    for (const QString &layer : project.layerPaths)
        layers.append(pathToDisk(layer, dir));
    json.insert(QStringLiteral("layers"), layers);
    Timeline timeline = project.timeline;
    QVector<AudioClip> clips = timeline.audioClips();
    for (AudioClip &clip : clips)
        clip.path = pathToDisk(clip.path, dir);
    timeline.setAudioClips(clips);
    if (std::optional<VideoClip> video = timeline.video()) {
        video->path = pathToDisk(video->path, dir);
        timeline.setVideo(video);
    }
    json.insert(QStringLiteral("timeline"), timeline.toJson());
    json.insert(QStringLiteral("syllables"), syllablesToJson(project.syllables));
    return json;
}

std::optional<Project> projectFromJson(const QJsonObject &json, const QString &projectDir, QString *error)
{
    QString scratch;
    if (!error)
        error = &scratch;
    const QDir dir(projectDir);
    const JsonField root(json, QString());

    const JsonField format = root.member("format");
    if (format.isMissing()) {
        *error = ProjectText::tr("not a Toonface project (it has no \"format\" field)");
        return std::nullopt;
    }
    if (format.value().toString() != QLatin1StringView(kProjectFormat)) {
        *error = ProjectText::tr("not a Toonface project (format: expected \"%1\", %2)")
                     .arg(QLatin1StringView(kProjectFormat), JsonField::describe(format.value()));
        return std::nullopt;
    }
    const JsonField versionField = root.member("version");
    int version = 0;
    if (!versionField.toInt(1, std::numeric_limits<int>::max(), &version, nullptr)) {
        versionField.expected(ProjectText::tr("a version number (1 or more)"), error);
        return std::nullopt;
    }
    if (version > kProjectVersion) {
        *error = ProjectText::tr("made by a newer Toonface (project version %1; this version reads up to %2)")
                     .arg(version)
                     .arg(kProjectVersion);
        return std::nullopt;
    }

    Project p;
    QString photo;
    if (!root.member("photo").toString(&photo, error))
        return std::nullopt;
    p.photoPath = pathFromDisk(photo, dir);

    const JsonField imageSize = root.member("imageSize");
    if (!imageSize.isMissing()) {
        QJsonObject unused;
        int w = 0;
        int h = 0;
        if (!imageSize.toObject(&unused, error) || !imageSize.member("width").toInt(0, 1000000, &w, error)
            || !imageSize.member("height").toInt(0, 1000000, &h, error))
            return std::nullopt;
        p.face.setImageSize(QSize(w, h));
    }
    if (!pointsFromJson(root.member("points"), &p.face, error) || !styleFromJson(root.member("style"), &p.style, error)
        || !mouthShapesFromJson(root.member("mouthShapes"), &p.mouthShapes, error))
        return std::nullopt;

    const JsonField layers = root.member("layers");
    QJsonArray layerArray;
    if (!layers.toArray(&layerArray, error))
        return std::nullopt;
    for (qsizetype i = 0; i < layerArray.size(); ++i) {
        QString layer;
        if (!layers.at(i).toString(&layer, error))
            return std::nullopt;
        if (layer.isEmpty()) {
            layers.at(i).expected(ProjectText::tr("a file path"), error);
            return std::nullopt;
        }
        p.layerPaths << pathFromDisk(layer, dir);
    }

    QJsonObject timelineJson;
    if (!root.member("timeline").toObject(&timelineJson, error))
        return std::nullopt;
    QString timelineError;
    std::optional<Timeline> timeline = Timeline::fromJson(timelineJson, &timelineError);
    if (!timeline) {
        *error = QStringLiteral("timeline.") + timelineError;
        return std::nullopt;
    }
    p.timeline = std::move(*timeline);

    QVector<AudioClip> clips = p.timeline.audioClips();
    for (AudioClip &clip : clips)
        clip.path = pathFromDisk(clip.path, dir);
    if (std::optional<VideoClip> video = p.timeline.video()) {
        video->path = pathFromDisk(video->path, dir);
        p.timeline.setVideo(video);
    }
    if (version >= 2) {
        p.timeline.setAudioClips(clips);
        const JsonField syllables = root.member("syllables");
        if (!syllables.isMissing() && !syllablesFromJson(syllables, &p.syllables, error))
            return std::nullopt;
        return p;
    }

    // Version 1: one sound, named by `audio` (which wins) and `timeline.audio`, and one script.
    const JsonField audio = root.member("audio");
    QJsonObject unused;
    QString audioPath;
    double audioOffset = 0;
    if (!audio.toObject(&unused, error) || !audio.member("path").toString(&audioPath, error)
        || !audio.member("offset").toNumber(&audioOffset, error))
        return std::nullopt;
    std::optional<AudioClip> clip;
    if (!clips.isEmpty())
        clip = clips.first();
    if (!audioPath.isEmpty()) {
        clip = clip.value_or(AudioClip {});
        clip->path = pathFromDisk(audioPath, dir);
        clip->offset = audioOffset;
    }

    const JsonField script = root.member("script");
    const JsonField language = script.member("language");
    QString text;
    QString languageCode;
    if (!script.toObject(&unused, error) || !script.member("text").toString(&text, error)
        || !language.toString(&languageCode, error))
        return std::nullopt;
    if (!languageCode.isEmpty() && languageCode != QLatin1StringView("cmn")
        && languageCode != QLatin1StringView("en")) {
        language.expected(ProjectText::tr("\"cmn\", \"en\" or \"\""), error);
        return std::nullopt;
    }
    // Older files have no syllables.
    const JsonField syllables = script.member("syllables");
    if (!syllables.isMissing() && !syllablesFromJson(syllables, &p.syllables, error))
        return std::nullopt;
    if (clip) {
        clip->script = text;
        clip->language = languageCode;
        p.timeline.setAudioClips({*clip});
    } else {
        p.timeline.setAudioClips({});
    }
    return p;
}

QStringList filesOutsideFolder(const Project &project, const QString &projectDir)
{
    const QString folder = QDir::cleanPath(QDir(projectDir).absolutePath()) + QLatin1Char('/');
    const QString realFolder = QFileInfo(projectDir).canonicalFilePath() + QLatin1Char('/');
    QStringList out;
    auto check = [&](const QString &what, const QString &path) {
        if (path.isEmpty())
            return;
        const QString absolute = QDir::cleanPath(QDir(projectDir).absoluteFilePath(path));
        // Links are followed: a link inside the folder to a file outside it is outside.
        const QString real = QFileInfo(absolute).canonicalFilePath();
        if (!absolute.startsWith(folder) || (!real.isEmpty() && !real.startsWith(realFolder)))
            out << ProjectText::tr("%1: %2").arg(what, QDir::toNativeSeparators(real.isEmpty() ? absolute : real));
    };
    check(ProjectText::tr("photo"), project.photoPath);
    for (const AudioClip &clip : project.timeline.audioClips())
        check(ProjectText::tr("sound"), clip.path);
    if (const std::optional<VideoClip> video = project.timeline.video())
        check(ProjectText::tr("video"), video->path);
    for (const QString &layer : project.layerPaths)
        check(ProjectText::tr("layer"), layer);
    return out;
}

bool saveProject(const Project &project, const QString &path, QString *error)
{
    QString scratch;
    if (!error)
        error = &scratch;
    const QString dir = QFileInfo(path).absolutePath();
    const QJsonObject json = projectToJson(project, dir);
    // Never write a file that loadProject would refuse (JSON has no NaN: it would become null).
    QString invalid;
    if (!projectFromJson(json, dir, &invalid)) {
        *error = withFile(path, ProjectText::tr("not saved: the project is invalid at %1").arg(invalid));
        return false;
    }
    const QByteArray bytes = QJsonDocument(json).toJson(QJsonDocument::Indented);

    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        *error = withFile(path, ProjectText::tr("cannot save: %1").arg(file.errorString()));
        return false;
    }
    const qint64 written = file.write(bytes);
    if (written != bytes.size()) {
        // A short write without an error code is what a full disk or a file size limit gives.
        const QString why = file.error() != QFileDevice::NoError
            ? writeProblem(file)
            : ProjectText::tr("only %1 of %2 bytes could be written (is the disk full?)")
                  .arg(qMax<qint64>(written, 0))
                  .arg(bytes.size());
        *error = withFile(path, ProjectText::tr("cannot save: %1").arg(why));
        file.cancelWriting();
        return false;
    }
    if (!file.commit()) {
        const QString why = file.error() != QFileDevice::NoError
            ? writeProblem(file)
            : ProjectText::tr("the file could not be completed (is the disk full?)");
        *error = withFile(path, ProjectText::tr("cannot save: %1").arg(why));
        return false;
    }
    return true;
}

std::optional<Project> loadProject(const QString &path, QString *error)
{
    QString scratch;
    if (!error)
        error = &scratch;
    const QFileInfo info(path);
    if (!info.exists()) {
        *error = withFile(path, ProjectText::tr("no such file"));
        return std::nullopt;
    }
    if (info.isDir()) {
        *error = withFile(path, ProjectText::tr("is a folder, not a Toonface project"));
        return std::nullopt;
    }
    if (info.size() > kMaxProjectBytes) {
        *error = withFile(path, ProjectText::tr("too large to be a Toonface project (%1 MB)").arg(info.size() >> 20));
        return std::nullopt;
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = withFile(path, ProjectText::tr("cannot read: %1").arg(file.errorString()));
        return std::nullopt;
    }
    const QByteArray bytes = file.readAll();
    if (bytes.trimmed().isEmpty()) {
        *error = withFile(path, ProjectText::tr("the file is empty, not a Toonface project"));
        return std::nullopt;
    }
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        const QByteArray before = bytes.left(parseError.offset);
        const qsizetype line = before.count('\n') + 1;
        const qsizetype column = before.size() - before.lastIndexOf('\n');
        *error = withFile(path,
            ProjectText::tr("not a Toonface project: %1 at offset %2 (line %3, column %4)")
                .arg(parseError.errorString())
                .arg(parseError.offset)
                .arg(line)
                .arg(column));
        return std::nullopt;
    }
    if (!doc.isObject()) {
        *error = withFile(path, ProjectText::tr("not a Toonface project (expected a JSON object, found an array)"));
        return std::nullopt;
    }
    QString problem;
    auto project = projectFromJson(doc.object(), info.absolutePath(), &problem);
    if (!project) {
        *error = withFile(path, problem);
        return project;
    }
    // Files of the one-sound format could name a sound without its length: the clip is as long
    // as its file, when the file can be read (else it stays of unknown length, 0).
    QVector<AudioClip> clips = project->timeline.audioClips();
    for (AudioClip &clip : clips) {
        QString unreadable;
        if (clip.duration > 0 || !irregularFileProblem(clip.path).isEmpty())
            continue;
        // The header's length when it has one (an hour of sound is not decoded to open a
        // project); only a container that does not say is decoded to be measured.
        double seconds = 0;
        if (const SoundCheck check = checkSound(clip.path); check.ok() && check.seconds > 0)
            seconds = check.seconds;
        else if (const std::optional<MediaInfo> media = probeMedia(clip.path, &unreadable); media && media->hasAudio)
            seconds = media->audioDurationS;
        if (seconds > 0)
            clip.duration = std::min(seconds, Timeline::kMaxSeconds - std::max(0.0, clip.offset));
    }
    project->timeline.setAudioClips(clips);
    return project;
}

} // namespace toonface
