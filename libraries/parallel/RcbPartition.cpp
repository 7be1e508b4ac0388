#include "parallel/RcbPartition.hpp"

#include <zoltan.h>

#include <limits>
#include <stdexcept>
#include <string>

namespace sph
{

namespace
{

template <int D>
struct Points
{
    const std::vector<Vec<D>>* x;
    const std::vector<std::uint64_t>* id;
};

template <int D>
int count(void* data, int* ierr)
{
    *ierr = ZOLTAN_OK;
    return static_cast<int>(static_cast<Points<D>*>(data)->x->size());
}

template <int D>
void list(void* data, int, int, ZOLTAN_ID_PTR global, ZOLTAN_ID_PTR local, int, float*, int* ierr)
{
    const auto& points = *static_cast<Points<D>*>(data);
    for (std::size_t i = 0; i < points.x->size(); ++i)
    {
        global[i] = static_cast<ZOLTAN_ID_TYPE>((*points.id)[i]);
        local[i] = static_cast<ZOLTAN_ID_TYPE>(i);
    }
    *ierr = ZOLTAN_OK;
}

template <int D>
int dimension(void*, int* ierr)
{
    *ierr = ZOLTAN_OK;
    return D;
}

template <int D>
void coordinates(void* data, int, int, int n, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR local, int dim,
                 double* geometry, int* ierr)
{
    const auto& points = *static_cast<Points<D>*>(data);
    for (int i = 0; i < n; ++i)
    {
        const Vec<D>& p = (*points.x)[local[i]];
        for (int d = 0; d < dim; ++d)
        {
            geometry[i * dim + d] = p[d];
        }
    }
    *ierr = ZOLTAN_OK;
}

void check(int status, const char* what)
{
    if (status != ZOLTAN_OK)
    {
        throw std::runtime_error(std::string("Zoltan: ") + what + " failed");
    }
}

} // namespace

template <int D>
std::vector<int> rcbOwners(const Communicator& comm, const std::vector<Vec<D>>& x,
                           const std::vector<std::uint64_t>& id)
{
    if (x.size() != id.size())
    {
        throw std::invalid_argument("rcbOwners: as many ids as positions needed");
    }
    std::vector<int> owner(x.size(), comm.rank());
    if (!comm.parallel())
    {
        return owner;
    }
    for (const std::uint64_t i : id)
    {
        if (i > std::numeric_limits<ZOLTAN_ID_TYPE>::max())
        {
            throw std::out_of_range("rcbOwners: a global id beyond Zoltan's id type");
        }
    }
    static const bool initialised = [] {
        float version = 0.0f;
        check(Zoltan_Initialize(0, nullptr, &version), "Zoltan_Initialize");
        return true;
    }();
    (void)initialised;

    Zoltan_Struct* zz = Zoltan_Create(MPI_COMM_WORLD);
    Points<D> points{&x, &id};
    Zoltan_Set_Param(zz, "DEBUG_LEVEL", "0");
    Zoltan_Set_Param(zz, "LB_METHOD", "RCB");
    Zoltan_Set_Param(zz, "NUM_GID_ENTRIES", "1");
    Zoltan_Set_Param(zz, "NUM_LID_ENTRIES", "1");
    Zoltan_Set_Param(zz, "OBJ_WEIGHT_DIM", "0");
    Zoltan_Set_Param(zz, "RETURN_LISTS", "EXPORT");
    Zoltan_Set_Param(zz, "KEEP_CUTS", "0");
    Zoltan_Set_Param(zz, "RCB_RECTILINEAR_BLOCKS", "0");
    Zoltan_Set_Num_Obj_Fn(zz, count<D>, &points);
    Zoltan_Set_Obj_List_Fn(zz, list<D>, &points);
    Zoltan_Set_Num_Geom_Fn(zz, dimension<D>, &points);
    Zoltan_Set_Geom_Multi_Fn(zz, coordinates<D>, &points);

    int changes = 0, gidEntries = 0, lidEntries = 0, imports = 0, exports = 0;
    ZOLTAN_ID_PTR importGlobal = nullptr, importLocal = nullptr, exportGlobal = nullptr,
                  exportLocal = nullptr;
    int *importProcs = nullptr, *importParts = nullptr, *exportProcs = nullptr,
        *exportParts = nullptr;
    const int status = Zoltan_LB_Partition(zz, &changes, &gidEntries, &lidEntries, &imports,
                                           &importGlobal, &importLocal, &importProcs,
                                           &importParts, &exports, &exportGlobal, &exportLocal,
                                           &exportProcs, &exportParts);
    if (status == ZOLTAN_OK)
    {
        for (int i = 0; i < exports; ++i)
        {
            owner[exportLocal[i]] = exportProcs[i];
        }
    }
    Zoltan_LB_Free_Part(&importGlobal, &importLocal, &importProcs, &importParts);
    Zoltan_LB_Free_Part(&exportGlobal, &exportLocal, &exportProcs, &exportParts);
    Zoltan_Destroy(&zz);
    check(status, "Zoltan_LB_Partition (RCB)");
    return owner;
}

template std::vector<int> rcbOwners<1>(const Communicator&, const std::vector<Vec<1>>&,
                                       const std::vector<std::uint64_t>&);
template std::vector<int> rcbOwners<2>(const Communicator&, const std::vector<Vec<2>>&,
                                       const std::vector<std::uint64_t>&);
template std::vector<int> rcbOwners<3>(const Communicator&, const std::vector<Vec<3>>&,
                                       const std::vector<std::uint64_t>&);

} // namespace sph
