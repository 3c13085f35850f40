#include "benchmark.h"

#include "export/epubbook.h"
#include "face/averageface.h"
#include "speech/audio.h"
#include "speech/script.h"
#include "speech/tts.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QRandomGenerator>
#include <QTemporaryDir>

#include <sys/resource.h>

#include <map>

using namespace toonface;

namespace {

double cpuMs()
{
    rusage u {};
    getrusage(RUSAGE_SELF, &u);
    return (double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1000.0)
        + double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1000.0;
}

// About `minutes` of reading at the voice's 175 words a minute (Chinese: about 4 syllables a
// second), in chapters of ten paragraphs of three to five sentences; the same every run.
QString bookText(bool chinese, double minutes)
{
    QRandomGenerator rng(29);
    const QStringList english = QStringLiteral(
        "the a little old fox dog house river morning evening garden window friend mother father teacher road "
        "city tree flower bird song light water stone bread table story book letter answer question")
                                    .split(QLatin1Char(' '));
    const QStringList verbs = QStringLiteral("sees finds likes opens reads writes carries watches remembers follows")
                                  .split(QLatin1Char(' '));
    const QString hanzi = QStringLiteral(
        "我你他们的是在有不人这中大为上个国到说时要就出会可也和对生能而子那得于着下自之年过发后作里用道行所然家种事成方"
        "多经么去法学如都同现当没动面起看定天分还进好小部其些主样理心她本前开但因只从想实日军者意无力它与长把机十民第公"
        "此已工使情明性知全三又关点正业外将两高间由问很最重并物手应战向头文体政美相见被利什二等产或新己制身果加西斯月话"
        "合回特代内信表化老给世位次度门任常先海通教儿原东声提立及比员解水名真论处走义各入几口认条平系气题活尔更别打女变"
        "四神总何电数安少报才结反受目太量再感建务做接必场件计管期市直德资命山金指克许统区保至队形社便空决治展马科司五基"
        "眼书非则听白却界达光放强即像难且权思王象完设式色路记南品住告类求据程北边死张该交规万取拉格望觉术领共确传师观清"
        "今切院让识候带导争运笑飞风步改收根干造言联持组每济车亲极林服快办议往元英士证近失转夫令准布始怎呢存未远叫台单影"
        "具罗字爱击流备兵连调深商算质团集百需价花党华城石级整府离况亚请技际约示复病息究线似官火断精满支视消越器容照须九"
        "增研写称企八功吗包片史委乎查轻易早曾除农找装广显吧阿李标谈吃图念六引历首医局突专费号尽另周较注语仅考落青随选列"
        "武红响虽推势参希古众构房半节土投某案黑维革划敌致陈律足态护七兴派孩验责营星够章音跟志底站严巴例防族供效续施留讲"
        "型料终答紧黄绝奇察母京段依批群项故按河米围江织害斗双境客纪采举杀攻父苏密低朝友诉止细愿千值仍男钱破网热助倒育属"
        "坐帝限船脸职速刻乐否刚威毛状率甚独球般普怕弹校苦创假久错承印晚兰试股拿脑预谁益阳若哪微尼继送急血惊伤素药适波夜"
        "省初喜卫源食险待述陆习置居劳财环排福纳欢雷警获模充负云停木游龙树疑层冷洲冲射略范竟句室异激汉村哈策演简卡罪判担"
        "州静退既衣您宗积余痛检差富灵协角占配征修皮挥胜降阶审沉坚善妈刘读啊超免压银买皇养伊怀执副乱抗犯追帮宣佛岁航优怪"
        "香著田铁控税左右份穿艺背阵草脚概恶块顿敢守酒岛托央户烈洋哥索胡款靠评版宝座释景顾弟登货互付伯慢欧换闻危忙核暗姐"
        "介坏讨丽良序升监临亮露永呼味野架域沙掉括舰鱼杂误湾吉减编楚肯测败屋跑梦散温困剑渐封救贵枪缺楼县尚毫移娘朋画班智"
        "亦耳恩短掌恐遗固席松秘谢鲁遇康虑幸均销钟诗藏赶剧票损忽巨炮旧端探湖录叶春乡附吸予礼港雨呀板庭妇归睛饭额含顺输摇"
        "招婚脱补谓督毒油疗旅泽材灭逐莫笔亡鲜词圣择寻厂睡博勒烟授诺伦岸奥唐卖俄炸载洛健堂旁宫喝借君禁阴园谋宋避抓荣姑孙"
        "逃牙束跳顶玉镇雪午练迫爷篇肉嘴馆遍凡础洞卷坦牛宁纸诸训私庄祖丝翻暴森塔默握戏隐熟骨访弱蒙歌店鬼软典欲萨伙遭盘爸"
        "扩盖弄雄稳忘亿刺拥徒姆杨齐赛趣曲刀床迎冰虚玩析窗醒妻透购替塞努休虎扬途侵刑绿兄迅套贸毕唯谷轮库迹尤竞街促延震弃"
        "甲伟麻川申缓潜闪售灯针哲络抵朱埃抱鼓植纯夏忍页杰筑折郑贝尊吴秀混臣雅振染盛怒舞圆搞狂措姓残秋培迷诚宽宇猛摆梅毁"
        "伸摩盟末乃悲拍丁赵");
    QString text;
    double spoken = 0; // seconds
    const double target = minutes * 60;
    for (int chapter = 1; spoken < target; ++chapter) {
        // Chinese chapter numbers in characters: digits are not read aloud.
        const QString number = QStringView(u"一二三四五六七八九十").mid((chapter - 1) % 10, 1).toString();
        text += chinese ? QStringLiteral("# 第%1章\n\n").arg(number) : QStringLiteral("# Chapter %1\n\n").arg(chapter);
        for (int p = 0; p < 10 && spoken < target; ++p) {
            const int sentences = 3 + int(rng.bounded(3));
            for (int s = 0; s < sentences; ++s) {
                const int length = 8 + int(rng.bounded(8));
                if (chinese) {
                    for (int w = 0; w < length; ++w)
                        text += hanzi[int(rng.bounded(qsizetype(hanzi.size())))];
                    text += QStringView(u"。。！？").at(int(rng.bounded(4)));
                    spoken += length / 4.0;
                } else {
                    QStringList words;
                    for (int w = 0; w < length; ++w)
                        words << (w == length / 2
                                ? verbs
                                : english)[int(rng.bounded(qsizetype((w == length / 2 ? verbs : english).size())))];
                    QString sentence = words.join(QLatin1Char(' '));
                    sentence[0] = sentence[0].toUpper();
                    text += sentence + QStringView(u"..!?").at(int(rng.bounded(4))) + QLatin1Char(' ');
                    spoken += length * 60.0 / 175.0;
                }
            }
            text += QStringLiteral("\n\n");
        }
    }
    return text;
}

// Makes the book of `text`, read by the voice or from `recording`; its figures.
QJsonObject makeBook(const QString &text, const QString &recording, BookFaceMedia faceMedia = BookFaceMedia::Svg)
{
    QTemporaryDir dir;
    const QString textPath = dir.filePath(QStringLiteral("book.md"));
    QFile f(textPath);
    if (!f.open(QIODevice::WriteOnly))
        return {{QStringLiteral("error"), f.errorString()}};
    f.write(text.toUtf8());
    f.close();
    BookRequest request;
    request.textPath = textPath;
    request.audioPath = recording;
    request.outputPath = dir.filePath(QStringLiteral("book.epub"));
    request.face = averageFace(QRectF(106, 130, 300, 330), QSize(512, 512));
    request.style = Style::preset(QStringLiteral("normal"));
    request.faceMedia = faceMedia;
    std::map<QString, double> stages;
    QElapsedTimer clock;
    QString stage = QStringLiteral("start");
    qint64 last = 0;
    const double cpuBefore = cpuMs();
    clock.start();
    const BookResult result = exportBook(request, [&](double, const QString &now) {
        // Chapter numbers apart: "reading chapter 3 of 6 aloud" counts as reading aloud.
        const qint64 t = clock.elapsed();
        stages[stage] += double(t - last);
        last = t;
        stage = now.contains(QLatin1StringView("chapter")) ? QStringLiteral("reading aloud") : now;
    });
    const double wall = double(clock.elapsed());
    stages[stage] += wall - double(last);
    if (!result.ok())
        return {{QStringLiteral("error"), result.error}};
    QJsonObject stageMs;
    for (const auto &[name, ms] : stages)
        stageMs.insert(name, std::round(ms));
    QJsonObject figures = bench::loadAverage();
    const QJsonObject measured {
        {QStringLiteral("audioMinutes"), std::round(result.duration / 6.0) / 10.0},
        {QStringLiteral("chapters"), result.chapters},
        {QStringLiteral("pages"), result.pages},
        {QStringLiteral("sentences"), int(result.sentences.size())},
        {QStringLiteral("wallMs"), std::round(wall)},
        {QStringLiteral("cpuMs"), std::round(cpuMs() - cpuBefore)},
        {QStringLiteral("secondsPerTenMinutes"), std::round(wall / result.duration * 600.0 / 100.0) / 10.0},
        {QStringLiteral("megabytes"), std::round(double(QFileInfo(request.outputPath).size()) / 1e5) / 10.0},
        {QStringLiteral("stageMs"), stageMs},
    };
    for (auto it = measured.begin(); it != measured.end(); ++it)
        figures.insert(it.key(), it.value());
    return figures;
}

QJsonObject benchSayEnglish()
{
    return makeBook(bookText(false, 10), {});
}

QJsonObject benchSayChinese()
{
    return makeBook(bookText(true, 10), {});
}

// The face as a video per page: the 10-minute book with every page's video drawn and
// encoded (cpuMs against wallMs shows how much of both cores it used).
QJsonObject benchSayEnglishVideo()
{
    return makeBook(bookText(false, 10), {}, BookFaceMedia::Video);
}

// The text of `text` as the voice reads it: headings without their marks.
QString spokenText(const QString &text)
{
    QString spoken;
    for (const QString &line : text.split(QLatin1Char('\n'))) {
        if (!line.trimmed().isEmpty())
            spoken += (line.startsWith(QLatin1Char('#')) ? line.mid(line.indexOf(QLatin1Char(' ')) + 1) : line)
                + QLatin1Char('\n');
    }
    return spoken;
}

// An hour-long --audio through toonface-cli book, against ten minutes of the same: the process's
// peak memory and CPU time. The recording is ten minutes of the voice reading the 10-minute text
// repeated (FLAC, written a block at a time), the text the same repeated.
QJsonObject benchRecordedHour()
{
    const QString ten = bookText(false, 10);
    const ScriptParse script = parseScript(spokenText(ten), Language::English);
    TtsResult spoken = synthesize(script.script);
    if (!spoken.ok())
        return {{QStringLiteral("error"), spoken.error}};
    QTemporaryDir dir;
    QJsonObject out = bench::loadAverage();
    for (const int repeats : {1, 6}) {
        const QString name = QStringLiteral("%1min").arg(repeats * 10);
        const QString flac = dir.filePath(name + QStringLiteral(".flac"));
        const QString textPath = dir.filePath(name + QStringLiteral(".md"));
        QString error;
        std::unique_ptr<AudioFileWriter> writer = openAudioFileWriter(flac, spoken.audio.sampleRate, &error);
        for (int k = 0; writer && k < repeats; ++k) {
            if (!writer->write(spoken.audio.samples.constData(), spoken.audio.samples.size(), &error))
                writer.reset();
        }
        QFile f(textPath);
        if (!writer || !writer->finish(&error) || !f.open(QIODevice::WriteOnly))
            return {{QStringLiteral("error"), error.isEmpty() ? f.errorString() : error}};
        f.write(ten.repeated(repeats).toUtf8());
        f.close();
        // The aligner alone (lipsync of the same recording and text), then the whole book.
        const QString script = dir.filePath(name + QStringLiteral(".txt"));
        QFile spokenFile(script);
        if (!spokenFile.open(QIODevice::WriteOnly))
            return {{QStringLiteral("error"), spokenFile.errorString()}};
        spokenFile.write(spokenText(ten).repeated(repeats).toUtf8());
        spokenFile.close();
        const bench::ChildRun aligned = bench::runMeasured(QStringLiteral(TOONFACE_CLI_PATH),
            {QStringLiteral("lipsync"), QStringLiteral("--audio"), flac, QStringLiteral("--script"), script,
                QStringLiteral("--lang"), QStringLiteral("en"), QStringLiteral("-o"),
                dir.filePath(name + QStringLiteral(".json"))},
            {QStringLiteral("QT_QPA_PLATFORM=offscreen")}, true);
        const QJsonObject aligner = aligned.ok
            ? QJsonObject {{QStringLiteral("wallMs"), qRound(aligned.wallMs)},
                {QStringLiteral("cpuMs"), qRound(aligned.cpuMs)}, {QStringLiteral("peakMb"), qRound(aligned.peakMb)}}
            : QJsonObject {{QStringLiteral("error"), QString::fromUtf8(aligned.stderrText)}};
        const bench::ChildRun run = bench::runMeasured(QStringLiteral(TOONFACE_CLI_PATH),
            {QStringLiteral("book"), textPath, QStringLiteral("--audio"), flac, QStringLiteral("-o"),
                dir.filePath(name + QStringLiteral(".epub"))},
            {QStringLiteral("QT_QPA_PLATFORM=offscreen")}, true);
        if (!run.ok) {
            out.insert(name,
                QJsonObject {{QStringLiteral("error"), QString::fromUtf8(run.stderrText)},
                    {QStringLiteral("aligner"), aligner}});
            continue;
        }
        out.insert(name,
            QJsonObject {{QStringLiteral("aligner"), aligner}, {QStringLiteral("wallMs"), qRound(run.wallMs)},
                {QStringLiteral("cpuMs"), qRound(run.cpuMs)}, {QStringLiteral("peakMb"), qRound(run.peakMb)},
                {QStringLiteral("recordingMb"), std::round(double(QFileInfo(flac).size()) / 1e5) / 10.0},
                {QStringLiteral("bookMb"),
                    std::round(double(QFileInfo(dir.filePath(name + QStringLiteral(".epub"))).size()) / 1e5) / 10.0}});
    }
    return out;
}

// A recording of the text (the voice's, written to a file first) aligned to it.
QJsonObject benchRecorded()
{
    const QString text = bookText(false, 10);
    QTemporaryDir dir;
    const ScriptParse script = parseScript(spokenText(text), Language::English);
    const TtsResult spoken = synthesize(script.script);
    const QString wav = dir.filePath(QStringLiteral("reading.wav"));
    QString error;
    if (!spoken.ok() || !writeAudio(wav, spoken.audio, &error))
        return {{QStringLiteral("error"), spoken.ok() ? error : spoken.error}};
    return makeBook(text, wav);
}

} // namespace

// A 10-minute book (the target: built in 60 s at most on 2 cores).
TOONFACE_BENCHMARK("book.say10minEnglish", benchSayEnglish);
TOONFACE_BENCHMARK("book.say10minChinese", benchSayChinese);
TOONFACE_BENCHMARK("book.recorded10minEnglish", benchRecorded);
TOONFACE_BENCHMARK("book.say10minEnglishVideo", benchSayEnglishVideo);
// Streaming: an hour-long recording's peak memory and time against ten minutes' (issue 29).
TOONFACE_BENCHMARK("book.recordedHour", benchRecordedHour);
