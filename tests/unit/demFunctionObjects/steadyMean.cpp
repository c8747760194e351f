// steadyMean (iceResistance's steady window and error) on series with known
// answers:
//  - a transient 30 exp(-i/(0.02 n)) on white noise of unit sd: MSER-5 cuts
//    where the transient has fallen below the noise, after 5 % of the series
//    (amplitude 30 e^-2.5 = 2.5 sd) and before 35 %, and the mean of the
//    window is the noise mean within 3 standard errors
//  - white noise of known sd: the batch-means standard error is sd/sqrt(n)
//    (10 batches: one estimate scatters by ~24 %, so the ratio is averaged
//    over 20 seeds and must lie within 10 % of 1)
//  - an AR(1) series (phi = 0.9): the batch-means error matches the true
//    standard error of the mean, 1/((1-phi) sqrt(n)) for innovations of
//    unit sd, within 15 % over 20 seeds, where the naive sd/sqrt(n) is 4.4
//    times too small
//  - a constant series: zero error, window from the start
#include "steadyMean.H"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using Foam::steadyMean;

TEST(SteadyMean, mserCutsTheTransient)
{
    std::mt19937_64 rng(5);
    std::normal_distribution<double> noise(0, 1);
    const int n = 5000;
    std::vector<double> x(n);
    for (int i = 0; i < n; ++i)
    {
        x[i] = 10 + noise(rng) + 30 * std::exp(-double(i) / (0.02 * n));
    }
    const long cut = steadyMean::mser5(x);
    EXPECT_GE(cut, long(0.05 * n));
    EXPECT_LE(cut, long(0.35 * n));
    const steadyMean::result r = steadyMean::over(x, cut, 10);
    EXPECT_NEAR(r.mean, 10, 3 * r.stdError);
    EXPECT_EQ(r.samples, n - cut);
}

TEST(SteadyMean, batchErrorOfWhiteNoise)
{
    const int n = 4000;
    double ratio = 0;
    for (int seed = 1; seed <= 20; ++seed)
    {
        std::mt19937_64 rng(seed);
        std::normal_distribution<double> noise(0, 2);
        std::vector<double> x(n);
        for (double& v : x) v = noise(rng);
        ratio += steadyMean::over(x, 0, 10).stdError / (2 / std::sqrt(double(n)));
    }
    EXPECT_NEAR(ratio / 20, 1, 0.1);
}

TEST(SteadyMean, batchErrorOfCorrelatedSeries)
{
    const int n = 20000;
    const double phi = 0.9;
    // var(x) = 1/(1 - phi^2); SE^2 = var(x) (1 + phi)/(1 - phi)/n
    const double sdTrue = 1 / ((1 - phi) * std::sqrt(double(n)));
    double ratio = 0;
    for (int seed = 1; seed <= 20; ++seed)
    {
        std::mt19937_64 rng(100 + seed);
        std::normal_distribution<double> noise(0, 1);
        std::vector<double> x(n);
        double y = 0;
        for (double& v : x) v = y = phi * y + noise(rng);
        ratio += steadyMean::over(x, 0, 10).stdError / sdTrue;
    }
    EXPECT_NEAR(ratio / 20, 1, 0.15);
}

TEST(SteadyMean, constantSeries)
{
    const std::vector<double> x(100, 3.5);
    EXPECT_EQ(steadyMean::mser5(x), 0);
    const steadyMean::result r = steadyMean::over(x, 0, 10);
    EXPECT_DOUBLE_EQ(r.mean, 3.5);
    EXPECT_DOUBLE_EQ(r.stdError, 0);
}
