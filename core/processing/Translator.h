#pragma once
// Translation of the text a processor shows (names, descriptions, parameter and input help).
//
// A family translates in the context of its namespace ("athlos::lps"), the context lupdate gives to
// tr("…") calls written inside that namespace. A processor file declares, in the family namespace,
//   namespace { constexpr Translator tr{"athlos::lps"}; }
// and writes tr("LPS positioning (TDoA)") as a Qt class would.
#include <QCoreApplication>
#include <QString>

namespace athlos {

struct Translator {
    const char* context;

    QString operator()(const char* text) const { return QCoreApplication::translate(context, text); }
};

}  // namespace athlos
