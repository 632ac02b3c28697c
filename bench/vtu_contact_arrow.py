"""The contact-force arrows of a 3D run's VTU frames as ParaView draws them:
the slabs and members warped by `displacement`, and a Glyph (arrows,
oriented and scaled by `contact_force`) of the same frame, rendered to a PNG
to look at (the arrows must stand clear of the slabs).

  pvbatch bench/vtu_contact_arrow.py SOLUTION.pvd TIME OUT.png [SCALE [X Y Z]]

SCALE: metres of arrow per newton (default 3e-6); X Y Z: a point to look at
from 12 m away (default: the whole model). pvbatch needs an X
display (Xvfb :N and DISPLAY=:N; pvpython under xvfb-run could not open one
here, pvbatch could)."""
import sys

from paraview.simple import (GetActiveViewOrCreate, Glyph, PVDReader, Render, SaveScreenshot,
                             Show, WarpByVector, ColorBy)

pvd, time, png = sys.argv[1], float(sys.argv[2]), sys.argv[3]
scale = float(sys.argv[4]) if len(sys.argv) > 4 else 3e-6
reader = PVDReader(FileName=pvd)
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [1200, 900]
view.ViewTime = time
warped = WarpByVector(Input=reader, Vectors=["POINTS", "displacement"], ScaleFactor=1.0)
model = Show(warped, view)
ColorBy(model, ("CELLS", "kind"))
arrows = Glyph(Input=warped, GlyphType="Arrow")
arrows.OrientationArray = ["POINTS", "contact_force"]
arrows.ScaleArray = ["POINTS", "contact_force"]
arrows.ScaleFactor = scale
arrows.GlyphMode = "All Points"
shown = Show(arrows, view)
shown.ColorArrayName = [None, ""]
shown.DiffuseColor = [1, 0, 0]
view.CameraViewUp = [0, 0, 1]
if len(sys.argv) > 7:
    at = [float(x) for x in sys.argv[5:8]]
    view.CameraFocalPoint = at
    view.CameraPosition = [at[0] + 6, at[1] - 8, at[2] + 7]
else:
    view.CameraPosition = [40, -40, 40]
    view.CameraFocalPoint = [10, 5, 10]
    view.ResetCamera()
Render(view)
SaveScreenshot(png, view, ImageResolution=[1200, 900])
