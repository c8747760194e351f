// Built only where LIGGGHTS is installed (Debian's libliggghts-dev)
#if __has_include(<liggghts/library_cfd_coupling.h>)

#include "liggghtsLibrary.H"

// MPI's C API only (its C++ bindings are not used); the MPI and LIGGGHTS
// headers are not written for OpenFOAM's warning flags
#define OMPI_SKIP_MPICXX 1
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wcast-function-type"
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#include <mpi.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <unistd.h>

// LIGGGHTS (Debian: /usr/include/liggghts)
#include <liggghts/lammps.h>
#include <liggghts/library.h>
#include <liggghts/library_cfd_coupling.h>
#include <liggghts/atom.h>
#include <liggghts/modify.h>
#include <liggghts/update.h>
#include <liggghts/memory.h>
#include <liggghts/fix_gravity.h>
#include <liggghts/fix_cfd_coupling.h>
#include <liggghts/cfd_datacoupling_mpi.h>
#pragma GCC diagnostic pop


namespace
{
using LAMMPS_NS::LAMMPS;

//- What the library is running now, for the message at exit
std::string running;
std::string screenOfRunning;

//- LIGGGHTS's Error::all ends the process with exit(1) from inside a call:
//  say so on stderr, with the ERROR lines it wrote to its screen file
void reportLiggghtsExit()
{
    if (running.empty())
    {
        return;
    }
    std::cerr << "\n--> Hedra: LIGGGHTS stopped the run while running "
        << running << "\n    its screen output: " << screenOfRunning << '\n';
    std::ifstream is(screenOfRunning);
    std::string line;
    while (std::getline(is, line))
    {
        if (line.find("ERROR") != std::string::npos)
        {
            std::cerr << "    " << line << '\n';
        }
    }
    std::cerr << std::endl;
}

//- MPI initialised here (serial solver run): finalise at exit
void finaliseMpi()
{
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (!finalised)
    {
        MPI_Finalize();
    }
}

LAMMPS* lmp(void* p)
{
    return static_cast<LAMMPS*>(p);
}
}


void Foam::liggghtsLibrary::begin(const std::string& what) const
{
    running = what;
    screenOfRunning = screenFile_;
}


void Foam::liggghtsLibrary::end() const
{
    running.clear();
}


Foam::liggghtsLibrary::liggghtsLibrary
(
    bool allRanks,
    const std::string& screenFile
)
:
    lmp_(nullptr),
    allRanks_(allRanks),
    screenFile_(screenFile),
    x_(nullptr),
    v_(nullptr),
    omega_(nullptr),
    radius_(nullptr),
    rmass_(nullptr),
    density_(nullptr),
    force_(nullptr),
    torque_(nullptr),
    type_(nullptr),
    rows_(-1)
{
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised)
    {
        MPI_Init(nullptr, nullptr);
        std::atexit(finaliseMpi);
    }
    static bool reporting = false;
    if (!reporting)
    {
        // Registered after finaliseMpi: runs before it
        std::atexit(reportLiggghtsExit);
        reporting = true;
    }

    std::vector<std::string> args
    {
        "liggghts", "-log", "none", "-screen", screenFile_
    };
    std::vector<char*> argv;
    for (std::string& a : args)
    {
        argv.push_back(&a[0]);
    }
    begin("lammps_open");
    lammps_open
    (
        int(argv.size()),
        argv.data(),
        allRanks_ ? MPI_COMM_WORLD : MPI_COMM_SELF,
        &lmp_
    );
    end();
}


Foam::liggghtsLibrary::~liggghtsLibrary()
{
    if (!lmp_)
    {
        return;
    }
    LAMMPS_NS::Memory* mem = lmp(lmp_)->memory;
    mem->destroy(x_);
    mem->destroy(v_);
    mem->destroy(omega_);
    mem->destroy(radius_);
    mem->destroy(rmass_);
    mem->destroy(density_);
    mem->destroy(force_);
    mem->destroy(torque_);
    mem->destroy(type_);
    lammps_close(lmp_);
}


void Foam::liggghtsLibrary::file(const std::string& script)
{
    begin("the input script " + script);
    lammps_file(lmp_, const_cast<char*>(script.c_str()));
    end();
}


void Foam::liggghtsLibrary::command(const std::string& line)
{
    begin("the command '" + line + "'");
    lammps_command(lmp_, const_cast<char*>(line.c_str()));
    end();
}


bool Foam::liggghtsLibrary::hasFixStyle(const std::string& style) const
{
    return lmp(lmp_)->modify->n_fixes_style_strict(style.c_str()) > 0;
}


bool Foam::liggghtsLibrary::mpiCoupling() const
{
    auto* fc = dynamic_cast<LAMMPS_NS::FixCfdCoupling*>
    (
        lmp(lmp_)->modify->find_fix_style_strict("couple/cfd", 0)
    );
    return
        fc
     && dynamic_cast<LAMMPS_NS::CfdDatacouplingMPI*>(fc->get_dc()) != nullptr;
}


bool Foam::liggghtsLibrary::hasAtomVector(const std::string& name) const
{
    return
        lmp(lmp_)->modify->find_fix_property
        (
            name.c_str(), "property/atom", "vector", 0, 0, "Hedra", false
        ) != nullptr;
}


bool Foam::liggghtsLibrary::atomMap() const
{
    return lmp(lmp_)->atom->map_style != 0;
}


bool Foam::liggghtsLibrary::granularAtoms() const
{
    const LAMMPS_NS::Atom* a = lmp(lmp_)->atom;
    return a->radius_flag && a->rmass_flag && a->omega_flag;
}


double Foam::liggghtsLibrary::timeStep() const
{
    return lmp(lmp_)->update->dt;
}


double Foam::liggghtsLibrary::time() const
{
    const LAMMPS_NS::Update* u = lmp(lmp_)->update;
    return u->atime + double(u->ntimestep - u->atimestep)*u->dt;
}


long long Foam::liggghtsLibrary::step() const
{
    return lmp(lmp_)->update->ntimestep;
}


int Foam::liggghtsLibrary::nTypes() const
{
    return lmp(lmp_)->atom->ntypes;
}


std::array<double, 3> Foam::liggghtsLibrary::gravity() const
{
    std::array<double, 3> g{0, 0, 0};
    LAMMPS_NS::Modify* m = lmp(lmp_)->modify;
    const int n = m->n_fixes_style_strict("gravity");
    for (int k = 0; k < n; ++k)
    {
        auto* fg = static_cast<LAMMPS_NS::FixGravity*>
        (
            m->find_fix_style_strict("gravity", k)
        );
        double a[3] = {0, 0, 0};
        fg->get_gravity(a);
        for (int c = 0; c < 3; ++c)
        {
            g[c] += a[c];
        }
    }
    return g;
}


int Foam::liggghtsLibrary::rank() const
{
    int r = 0;
    MPI_Comm_rank(lmp(lmp_)->world, &r);
    return r;
}


std::string Foam::liggghtsLibrary::workingDirectory()
{
    char buf[4096];
    return getcwd(buf, sizeof(buf)) ? std::string(buf) : std::string(".");
}


std::vector<double> Foam::liggghtsLibrary::typeDensities() const
{
    const LAMMPS_NS::Atom* a = lmp(lmp_)->atom;
    const int nt = a->ntypes;
    std::vector<double> lo(nt, 1e300), hi(nt, -1e300);
    for (int i = 0; i < a->nlocal; ++i)
    {
        const int t = a->type[i] - 1;
        const double rho =
            a->density
          ? a->density[i]
          : a->rmass[i]/(4.0/3.0*M_PI*a->radius[i]*a->radius[i]*a->radius[i]);
        lo[t] = std::min(lo[t], rho);
        hi[t] = std::max(hi[t], rho);
    }
    std::vector<double> gLo(nt), gHi(nt);
    MPI_Allreduce(lo.data(), gLo.data(), nt, MPI_DOUBLE, MPI_MIN, lmp(lmp_)->world);
    MPI_Allreduce(hi.data(), gHi.data(), nt, MPI_DOUBLE, MPI_MAX, lmp(lmp_)->world);
    std::vector<double> rho(nt, 0);
    for (int t = 0; t < nt; ++t)
    {
        if (gHi[t] < gLo[t])
        {
            rho[t] = 0;             // no atoms of the type
        }
        else if (gHi[t] - gLo[t] > 1e-12*gHi[t])
        {
            rho[t] = -1;            // mixed densities
        }
        else
        {
            rho[t] = gLo[t];
        }
    }
    return rho;
}


void Foam::liggghtsLibrary::allocate()
{
    // liggghts_get_maxtag: the rows the data coupling moves (collective)
    const int rows = liggghts_get_maxtag(lmp_);
    if (rows == rows_)
    {
        return;
    }
    allocate_external_double(x_, 3, "nparticles", 0.0, lmp_);
    allocate_external_double(v_, 3, "nparticles", 0.0, lmp_);
    allocate_external_double(omega_, 3, "nparticles", 0.0, lmp_);
    allocate_external_double(radius_, 1, "nparticles", 0.0, lmp_);
    allocate_external_double(rmass_, 1, "nparticles", 0.0, lmp_);
    allocate_external_double(density_, 1, "nparticles", 0.0, lmp_);
    allocate_external_double(force_, 3, "nparticles", 0.0, lmp_);
    allocate_external_double(torque_, 3, "nparticles", 0.0, lmp_);
    allocate_external_int(type_, 1, "nparticles", 0, lmp_);
    rows_ = rows;
}


void Foam::liggghtsLibrary::gather(atoms& a)
{
    allocate();
    begin("the data coupling (LIGGGHTS to Hedra)");
    auto pull = [this](const char* name, const char* kind, double**& d)
    {
        void* p = d;
        data_liggghts_to_of(name, kind, lmp_, p, "double");
    };
    pull("x", "vector-atom", x_);
    pull("v", "vector-atom", v_);
    pull("omega", "vector-atom", omega_);
    pull("radius", "scalar-atom", radius_);
    pull("rmass", "scalar-atom", rmass_);
    pull("density", "scalar-atom", density_);
    {
        void* p = type_;
        data_liggghts_to_of("type", "scalar-atom", lmp_, p, "int");
    }
    end();

    a = atoms();
    for (int r = 0; r < rows_; ++r)
    {
        if (radius_[r][0] <= 0)
        {
            continue;               // no atom with id r + 1
        }
        a.id.push_back(r + 1);
        a.type.push_back(type_[r][0]);
        a.radius.push_back(radius_[r][0]);
        a.mass.push_back(rmass_[r][0]);
        a.density.push_back(density_[r][0]);
        for (int c = 0; c < 3; ++c)
        {
            a.x.push_back(x_[r][c]);
            a.v.push_back(v_[r][c]);
            a.omega.push_back(omega_[r][c]);
        }
    }
}


void Foam::liggghtsLibrary::scatterForces
(
    const std::vector<int>& ids,
    const std::vector<double>& F,
    const std::vector<double>& T,
    bool contribute
)
{
    allocate();
    for (int r = 0; r < rows_; ++r)
    {
        for (int c = 0; c < 3; ++c)
        {
            force_[r][c] = 0;
            torque_[r][c] = 0;
        }
    }
    if (contribute)
    {
        for (std::size_t i = 0; i < ids.size(); ++i)
        {
            const int r = ids[i] - 1;
            if (r < 0 || r >= rows_)
            {
                continue;           // the atom is gone
            }
            for (int c = 0; c < 3; ++c)
            {
                force_[r][c] = F[3*i + c];
                torque_[r][c] = T.empty() ? 0 : T[3*i + c];
            }
        }
    }
    begin("the data coupling (Hedra to LIGGGHTS)");
    data_of_to_liggghts("dragforce", "vector-atom", lmp_, force_, "double");
    if (hasAtomVector("hdtorque"))
    {
        data_of_to_liggghts("hdtorque", "vector-atom", lmp_, torque_, "double");
    }
    end();
}

#endif
