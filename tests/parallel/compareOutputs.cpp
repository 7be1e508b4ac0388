// compareOutputs <serial .vtu> <distributed .pvtu, or another .vtu> [array...]
//
// Whether a distributed run's output is bit-identical to the serial run's: the .pvtu is read
// with VTK's own parallel reader (vtkXMLPUnstructuredGridReader, what ParaView uses), so a pass
// also shows that the pieces open as one dataset. Each particle is matched by its array
// "globalId" (its index in the serial file; a .vtu without it is in the serial order); the
// points and every named array (default: velocity, deformationGradient) must have the same
// bits. (Whole files are not compared: the energy audit's restart sums may differ at round-off.) Prints what differs; exit 0 when
// nothing does, 1 otherwise, 2 on bad usage or unreadable files.
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace
{

template <class Reader>
vtkSmartPointer<vtkUnstructuredGrid> read(const char* file)
{
    auto reader = vtkSmartPointer<Reader>::New();
    reader->SetFileName(file);
    reader->Update();
    vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
    if (!grid || grid->GetNumberOfPoints() == 0)
    {
        std::cerr << "compareOutputs: cannot read " << file << "\n";
        std::exit(2);
    }
    return grid;
}

// The tuple of `array` at `index`, as doubles.
std::vector<double> tuple(vtkDataArray* array, vtkIdType index)
{
    std::vector<double> values(static_cast<std::size_t>(array->GetNumberOfComponents()));
    array->GetTuple(index, values.data());
    return values;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 3)
    {
        std::cerr << "usage: compareOutputs <serial .vtu> <distributed .pvtu> [array...]\n";
        return 2;
    }
    std::vector<std::string> names(argv + 3, argv + argc);
    if (names.empty())
    {
        names = {"velocity", "deformationGradient"};
    }
    const auto serial = read<vtkXMLUnstructuredGridReader>(argv[1]);
    const std::string second = argv[2];
    const bool pieces = second.size() > 5 && second.compare(second.size() - 5, 5, ".pvtu") == 0;
    const auto distributed = pieces ? read<vtkXMLPUnstructuredGridReader>(argv[2])
                                    : read<vtkXMLUnstructuredGridReader>(argv[2]);
    vtkDataArray* ids = distributed->GetPointData()->GetArray("globalId");
    if (!ids && pieces)
    {
        std::cerr << "compareOutputs: " << argv[2] << " has no array globalId\n";
        return 2;
    }
    const vtkIdType n = serial->GetNumberOfPoints();
    if (distributed->GetNumberOfPoints() != n)
    {
        std::cout << "particle count: serial " << n << ", distributed "
                  << distributed->GetNumberOfPoints() << "\n";
        return 1;
    }
    std::vector<int> seen(static_cast<std::size_t>(n), 0);
    long differences = 0;
    const auto report = [&](const std::string& what, vtkIdType g, double a, double b) {
        if (differences++ < 10)
        {
            std::printf("%s of particle %lld: serial %.17g, distributed %.17g\n", what.c_str(),
                        static_cast<long long>(g), a, b);
        }
    };
    for (vtkIdType p = 0; p < n; ++p)
    {
        const auto g = ids ? static_cast<vtkIdType>(ids->GetTuple1(p)) : p;
        if (g < 0 || g >= n || seen[static_cast<std::size_t>(g)]++)
        {
            std::cout << "globalId " << g << " is out of range or appears twice\n";
            return 1;
        }
        double a[3], b[3];
        serial->GetPoint(g, a);
        distributed->GetPoint(p, b);
        for (int d = 0; d < 3; ++d)
        {
            if (a[d] != b[d])
            {
                report("position", g, a[d], b[d]);
            }
        }
        for (const std::string& name : names)
        {
            vtkDataArray* s = serial->GetPointData()->GetArray(name.c_str());
            vtkDataArray* q = distributed->GetPointData()->GetArray(name.c_str());
            if (!s || !q)
            {
                std::cerr << "compareOutputs: no array " << name << " in both files\n";
                return 2;
            }
            const auto x = tuple(s, g);
            const auto y = tuple(q, p);
            for (std::size_t c = 0; c < x.size(); ++c)
            {
                if (x[c] != y[c])
                {
                    report(name + "[" + std::to_string(c) + "]", g, x[c], y[c]);
                }
            }
        }
    }
    if (differences > 0)
    {
        std::cout << differences << " values differ\n";
        return 1;
    }
    std::cout << n << " particles: positions and " << names.size()
              << " arrays bit-identical\n";
    return 0;
}
