#pragma once
// Translation of the text a processor shows (names, descriptions, parameter and input help).
//
// A processor file declares, in its family namespace, a Translator with the family's context and
// the processor class:
//   namespace { constexpr Translator tr{"athlos::lps", "LpsCalibrationProcessor"}; }
// and writes tr("LPS positioning (TDoA)") as a Qt class would. lupdate (translations/, which reads
// the plugins' sources) files a tr("…") written in a member function under the class's context
// ("athlos::lps::LpsCalibrationProcessor") and one written in a free function under the namespace's
// ("athlos::lps"), so the class context is looked up first and the family's second.
#include <QByteArray>
#include <QCoreApplication>
#include <QString>

namespace athlos {

struct Translator {
    const char* context;              // the family's namespace, "athlos::lps"
    const char* className = nullptr;  // the processor class of the file, or none

    QString operator()(const char* text) const {
        if (className != nullptr) {
            const QByteArray scoped = QByteArray(context) + "::" + className;
            QString translated = QCoreApplication::translate(scoped.constData(), text);
            if (translated != QString::fromUtf8(text)) return translated;  // found there
        }
        return QCoreApplication::translate(context, text);
    }
};

}  // namespace athlos
