// Restart: 2N steps in one run equal N steps, a write and read of the state
// file, a fresh System, and N more steps — to the last bit (the reference
// positions of the neighbour lists and every contact spring are in the file).
#include "TestCase.hpp"

#include "polyDEM/RandomFill.hpp"
#include "polyDEM/StateIO.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <map>

using namespace polydem;

namespace
{

SimulationConfig pileConfig()
{
    const double r = 0.002;
    SimulationConfig cfg = test::sphereConfig(ContactLaw::hertzMindlin, 0.5, 0.5, r, 5e6);
    cfg.contact.rolling = RollingModel::elasticPlastic;
    cfg.pairs[0].rollingFriction = 0.1;
    cfg.gravity = Vec3(0, 0, -9.81);
    cfg.timeStep = 2e-5;
    cfg.planes = {test::plane(Vec3(0, 0, 0), Vec3(0, 0, 1)), test::plane(Vec3(0, 0, 0), Vec3(1, 0, 0)),
                  test::plane(Vec3(0.02, 0, 0), Vec3(-1, 0, 0)), test::plane(Vec3(0, 0, 0), Vec3(0, 1, 0)),
                  test::plane(Vec3(0, 0.02, 0), Vec3(0, -1, 0))};
    return cfg;
}

Snapshot initial(const System& s)
{
    const auto seeds = randomFill(FillRegion::box(Vec3(0, 0, 0), Vec3(0.02, 0.02, 0.05)),
                                  SizeDistribution::uniform(0.003, 0.004), 300, 11);
    std::vector<Vec3> x;
    std::vector<double> r;
    for (const auto& q : seeds)
    {
        x.push_back(q.position);
        r.push_back(q.radius);
    }
    Snapshot st;
    st.particles = s.makeSpheres(0, x, r, 0);
    return st;
}

} // namespace

TEST(Restart, bitExact)
{
    const int N = 3000;
    const std::string file = ::testing::TempDir() + "polydem_restart_state";
    for (StateFormat fmt : {StateFormat::ascii, StateFormat::binary})
    {
        System one(pileConfig());
        one.initialise(initial(one));
        one.advance(2 * N);
        const auto a = one.engine().particles();

        System first(pileConfig());
        first.initialise(initial(first));
        first.advance(N);
        ASSERT_GT(first.engine().statistics().contacts, 10u) << "the test needs springs to carry over";
        writeSnapshot(file, first.engine().snapshot(), fmt);

        System second(pileConfig());
        second.initialise(readSnapshot(file));
        EXPECT_EQ(second.engine().step(), N);
        second.advance(N);
        const auto b = second.engine().particles();
        std::remove(file.c_str());

        ASSERT_EQ(a.size(), b.size());
        std::map<std::int64_t, std::size_t> where;
        for (std::size_t i = 0; i < b.size(); ++i) where[b.id[i]] = i;
        for (std::size_t i = 0; i < a.size(); ++i)
        {
            const std::size_t j = where.at(a.id[i]);
            EXPECT_EQ(a.position[i].x, b.position[j].x);
            EXPECT_EQ(a.position[i].y, b.position[j].y);
            EXPECT_EQ(a.position[i].z, b.position[j].z);
            EXPECT_EQ(a.omega[i].x, b.omega[j].x);
        }
    }
}
