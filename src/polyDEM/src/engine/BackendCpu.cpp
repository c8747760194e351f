// polyDEM CPU back end: the Thrust engine on Thrust's OpenMP device system.
#define PD_BACKEND_NAME "cpu"
#define PD_BACKEND_NS cpu

#include "ThrustEngine.inl"

extern "C" __attribute__((visibility("default"))) polydem::Engine* polydemCreateEngine()
{
    return new polydem::cpu::ThrustEngine();
}
