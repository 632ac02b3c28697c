"""Open a run's field output in ParaView, as a user would, and say what it holds.

    xvfb-run -a pvpython scripts/paraview-check.py RESULTS_DIR [PNG]

RESULTS_DIR holds solution.pvd (Output/Field format = vtu) or solution.xdmf
(= xdmf). Prints the number of frames, points and cells, each array with its
range, and the frame with the largest contact force with its contact points;
with PNG, draws that frame: members and slabs coloured by building, the
contact forces as arrows. Needs Debian's python3-paraview (and xvfb without a
display); not part of the tests, which check the files' contents themselves
(cli/vtu, cli/vtu-3d, cli/xdmf). doc/verification.md, "Field output in
ParaView".
"""
import os
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import (CreateView, Glyph, PVDReader, ResetCamera, SaveScreenshot,
                             Show, ColorBy, Xdmf3ReaderS)
from vtk.numpy_interface import dataset_adapter


def open_output(directory):
    pvd = os.path.join(directory, "solution.pvd")
    xdmf = os.path.join(directory, "solution.xdmf")
    if os.path.exists(pvd):
        return PVDReader(FileName=pvd)
    if os.path.exists(xdmf):
        return Xdmf3ReaderS(FileName=[xdmf])
    sys.exit(f"paraview-check: no solution.pvd or solution.xdmf in {directory}")


def largest_contact_frame(reader, times):
    """The frame whose largest contact force is largest (None: no contact)."""
    best, best_force = None, 0.0
    for time in times:
        reader.UpdatePipeline(time)
        force = reader.PointData["contact_force"].GetRange(-1)[1]
        if force > best_force:
            best, best_force = time, force
    return best, best_force


def main():
    directory = sys.argv[1]
    reader = open_output(directory)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues or [0.0])
    reader.UpdatePipeline(times[-1])
    info = reader.GetDataInformation()
    print(f"{len(times)} frames, t = {times[0]} .. {times[-1]}; "
          f"{info.GetNumberOfPoints()} points, {info.GetNumberOfCells()} cells")
    for kind, arrays in (("point", reader.PointData), ("cell", reader.CellData)):
        for name in arrays.keys():
            print(f"  {kind} array {name} ({arrays[name].GetNumberOfComponents()} components): "
                  f"range {arrays[name].GetRange(-1)} at the last frame")
    if "contact_force" not in reader.PointData.keys():
        return
    time, force = largest_contact_frame(reader, times)
    if time is None:
        print("no contact in any frame")
        return
    reader.UpdatePipeline(time)
    data = dataset_adapter.WrapDataObject(servermanager.Fetch(reader))
    forces, points = data.PointData["contact_force"], data.Points
    for i in np.nonzero(np.linalg.norm(forces, axis=1))[0]:
        print(f"t = {time}: contact at {points[i]}, force {forces[i]} N")
    if len(sys.argv) > 2:
        view = CreateView("RenderView")
        view.ViewSize, view.ViewTime = [900, 700], time
        members = Show(reader, view)
        ColorBy(members, ("CELLS", "building"))
        members.Opacity = 0.35
        arrows = Glyph(Input=reader, GlyphType="Arrow")
        arrows.OrientationArray = ["POINTS", "contact_force"]
        arrows.ScaleArray = ["POINTS", "contact_force"]
        arrows.ScaleFactor = 0.2 * max(info.GetBounds()[1] - info.GetBounds()[0], 1.0) / force
        arrows.GlyphMode = "All Points"
        arrow_display = Show(arrows, view)
        arrow_display.ColorArrayName = ["POINTS", ""]  # one colour, not the building's
        arrow_display.DiffuseColor = arrow_display.AmbientColor = [1.0, 1.0, 0.0]
        view.CameraPosition, view.CameraViewUp = [-1.0, -1.7, 1.2], [0, 0, 1]
        ResetCamera(view)
        SaveScreenshot(sys.argv[2], view)


main()
