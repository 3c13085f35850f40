// An ordinary main for a fuzz target: runs LLVMFuzzerTestOneInput once on every file of the
// folders and files given, so that the seed corpus and the inputs that once failed are tested
// by ctest in every build, without libFuzzer. Exits 2 when a folder is missing or empty.

#include "fuzzinput.h"

#include <QCoreApplication>
#include <QDirIterator>
#include <QFileInfo>

#include <cstdio>

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments().mid(1);
    if (args.isEmpty()) {
        std::fprintf(stderr, "usage: %s CORPUS_DIR_OR_FILE...\n", argv[0]);
        return 2;
    }
    int inputs = 0;
    for (const QString &arg : args) {
        const QFileInfo info(arg);
        QStringList files;
        if (info.isDir()) {
            QDirIterator it(arg, QDir::Files, QDirIterator::Subdirectories);
            while (it.hasNext())
                files.append(it.next());
            files.sort();
        } else if (info.isFile()) {
            files.append(arg);
        } else {
            std::fprintf(stderr, "%s: no such file or folder\n", qPrintable(arg));
            return 2;
        }
        for (const QString &path : std::as_const(files)) {
            QFile file(path);
            if (!file.open(QIODevice::ReadOnly)) {
                std::fprintf(stderr, "%s: cannot read: %s\n", qPrintable(path), qPrintable(file.errorString()));
                return 2;
            }
            const QByteArray input = file.readAll();
            std::fprintf(stderr, "running %s (%lld bytes)\n", qPrintable(path), static_cast<long long>(input.size()));
            LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t *>(input.constData()), size_t(input.size()));
            ++inputs;
        }
    }
    if (inputs == 0) {
        std::fprintf(stderr, "no inputs found in %s\n", qPrintable(args.join(QStringLiteral(", "))));
        return 2;
    }
    std::printf("%d inputs ran\n", inputs);
    return 0;
}
