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
    QString sex; // m or f
    double browThickness = 0, browContrast = 0; // detect/browlook.h's measures
};

QStringList ageReport(const std::vector<AgeRow> &rows);
// The brows' measures' percentiles (10th, 50th, 90th) over all faces and their medians by age
// group and sex: what browlook.h's mapping is fitted to.
QStringList browReport(const std::vector<AgeRow> &rows);

} // namespace toonface::bench
