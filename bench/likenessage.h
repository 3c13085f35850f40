#pragma once

#include "detect/agegroup.h"

#include <QString>
#include <QStringList>

#include <vector>

// likeness.attributes' age group part (bench_likenessattributesage.cpp): the age models fitted
// and cross-validated over the labelled faces, and the shipped decision's figures.
namespace toonface::bench {

struct AgeRow
{
    QString label; // child, young, adult or elderly
    AgeEvidence evidence;
    AgeGroup shipped = AgeGroup::Adult;
};

QStringList ageReport(const std::vector<AgeRow> &rows);

} // namespace toonface::bench
