/*---------------------------------------------------------------------------*\
  Hedra: CFD-DEM for OpenFOAM
-------------------------------------------------------------------------------
Description
    MSER-5 truncation and batch means (see steadyMean.H).

\*---------------------------------------------------------------------------*/

#include "steadyMean.H"

#include <cmath>
#include <limits>

long Foam::steadyMean::mser5(const std::vector<double>& x)
{
    const long b = 5;
    const long m = long(x.size())/b;
    if (m < 2)
    {
        return 0;
    }
    std::vector<double> batch(m, 0);
    for (long j = 0; j < m; ++j)
    {
        for (long i = 0; i < b; ++i) batch[j] += x[j*b + i];
        batch[j] /= b;
    }
    long best = 0;
    double bestValue = std::numeric_limits<double>::infinity();
    for (long d = 0; d <= m/2; ++d)
    {
        const long n = m - d;
        double mean = 0;
        for (long j = d; j < m; ++j) mean += batch[j];
        mean /= n;
        double ss = 0;
        for (long j = d; j < m; ++j) ss += (batch[j] - mean)*(batch[j] - mean);
        const double v = ss/(double(n)*n);
        if (v < bestValue)
        {
            bestValue = v;
            best = d;
        }
    }
    return best*b;
}


Foam::steadyMean::result Foam::steadyMean::over
(
    const std::vector<double>& x,
    long start,
    long nBatches
)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    result r;
    r.start = start;
    r.samples = long(x.size()) - start;
    if (r.samples <= 0)
    {
        r.samples = 0;
        r.mean = r.stdError = r.batchCorrelation = nan;
        return r;
    }
    r.mean = 0;
    for (long i = start; i < long(x.size()); ++i) r.mean += x[i];
    r.mean /= r.samples;
    if (nBatches < 2 || r.samples < nBatches)
    {
        r.stdError = r.batchCorrelation = nan;
        return r;
    }
    std::vector<double> bm(nBatches, 0);
    for (long k = 0; k < nBatches; ++k)
    {
        const long i0 = start + k*r.samples/nBatches;
        const long i1 = start + (k + 1)*r.samples/nBatches;
        for (long i = i0; i < i1; ++i) bm[k] += x[i];
        bm[k] /= (i1 - i0);
    }
    double mean = 0;
    for (const double v : bm) mean += v;
    mean /= nBatches;
    double var = 0, cov = 0;
    for (long k = 0; k < nBatches; ++k)
    {
        var += (bm[k] - mean)*(bm[k] - mean);
        if (k > 0) cov += (bm[k] - mean)*(bm[k - 1] - mean);
    }
    r.stdError = std::sqrt(var/(nBatches - 1)/nBatches);
    r.batchCorrelation = var > 0 ? cov/var : 0;
    return r;
}
