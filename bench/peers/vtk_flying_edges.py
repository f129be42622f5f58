#!/usr/bin/python3
"""The VTK pipeline a graphics engineer would pick instead of FunctionLab's
mesher (issue 31 §3), as a benchmark peer only: a grid of samples (written
by functionlab-bench, raw little-endian float32, x fastest) contoured at 0
by vtkFlyingEdges3D with VTK's defaults, on the SMP backend with THREADS
threads. Prints one line of JSON: the least contouring time of REPEATS runs
in ms, the triangles and the backend; writes the triangles as binary STL.

usage: vtk_flying_edges.py GRID.raw NX NY NZ X0 Y0 Z0 HX HY HZ THREADS REPEATS OUT.stl
Needs Debian's python3-vtk9 (and no numpy)."""
import json
import sys
import time

import vtkmodules.all as vtk


def main(argv):
    if len(argv) != 14:
        print(__doc__, file=sys.stderr)
        return 2
    grid = argv[1]
    nx, ny, nz = (int(v) for v in argv[2:5])
    origin = [float(v) for v in argv[5:8]]
    spacing = [float(v) for v in argv[8:11]]
    threads, repeats, out = int(argv[11]), int(argv[12]), argv[13]
    smp = vtk.vtkSMPTools()
    smp.Initialize(threads)
    reader = vtk.vtkImageReader2()
    reader.SetFileName(grid)
    reader.SetFileDimensionality(3)
    reader.SetDataScalarTypeToFloat()
    reader.SetDataByteOrderToLittleEndian()
    reader.SetNumberOfScalarComponents(1)
    # Rows from y = 0 up (an image reader otherwise takes the first row as the top).
    reader.FileLowerLeftOn()
    reader.SetDataExtent(0, nx - 1, 0, ny - 1, 0, nz - 1)
    reader.SetDataOrigin(*origin)
    reader.SetDataSpacing(*spacing)
    reader.Update()
    image = vtk.vtkImageData()
    image.DeepCopy(reader.GetOutput())
    best = None
    contour = None
    for _ in range(max(1, repeats)):
        contour = vtk.vtkFlyingEdges3D()
        contour.SetInputData(image)
        contour.SetValue(0, 0.0)
        start = time.perf_counter()
        contour.Update()
        ms = (time.perf_counter() - start) * 1000
        best = ms if best is None else min(best, ms)
    mesh = contour.GetOutput()
    writer = vtk.vtkSTLWriter()
    writer.SetFileTypeToBinary()
    writer.SetFileName(out)
    writer.SetInputData(mesh)
    writer.Write()
    print(json.dumps({"ms": best, "triangles": mesh.GetNumberOfPolys(),
                      "backend": smp.GetBackend(), "threads": smp.GetEstimatedNumberOfThreads()}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
