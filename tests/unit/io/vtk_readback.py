#!/usr/bin/env python3
"""Reads what silodem writes for ParaView back with the real VTK library (python3-vtk9).

Usage: vtk_readback.py WRITE_VTK_SAMPLE   (the test program that writes the known state)
Checks particle counts, every field's values, the .pvd's times and files, and the silo surface.
Exits non-zero on the first mismatch.
"""
import math
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import vtk
from vtk.util.numpy_support import vtk_to_numpy


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def read(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    if reader.GetErrorCode() != 0:
        fail("VTK could not read {}".format(path))
    return reader.GetOutput()


def field(poly, name):
    arr = poly.GetPointData().GetArray(name)
    if arr is None:
        fail("no point array '{}'".format(name))
    return vtk_to_numpy(arr)


def close(a, b, tol=1e-12):
    return abs(a - b) <= tol * max(1.0, abs(b))


def main():
    with tempfile.TemporaryDirectory() as d:
        subprocess.run([sys.argv[1], d], check=True)
        # The .pvd collection: two frames at t = 0 and 0.5 s.
        sets = ET.parse(os.path.join(d, "particles.pvd")).getroot().findall("./Collection/DataSet")
        if [float(s.get("timestep")) for s in sets] != [0.0, 0.5]:
            fail("pvd times {}".format([s.get("timestep") for s in sets]))
        first = read(os.path.join(d, sets[0].get("file")))
        second = read(os.path.join(d, sets[1].get("file")))
        if first.GetNumberOfPoints() != 3 or second.GetNumberOfPoints() != 2:
            fail("point counts {} {}".format(first.GetNumberOfPoints(),
                                             second.GetNumberOfPoints()))
        if first.GetNumberOfVerts() != 3:
            fail("expected one vertex cell per particle, got {}".format(first.GetNumberOfVerts()))
        r = 0.004
        pts = vtk_to_numpy(first.GetPoints().GetData())
        if not all(close(a, b) for a, b in zip(pts[1], (2 * r * 0.999, 0.0, 0.1))):
            fail("position of particle 1: {}".format(pts[1]))
        radius = field(first, "radius")
        if not (close(radius[0], r) and close(radius[2], 1.5 * r)):
            fail("radius {}".format(radius))
        vel = field(first, "velocity")
        if vel.shape != (3, 3) or not close(vel[1][1], 0.4) or not close(vel[0][2], -0.3):
            fail("velocity {}".format(vel))
        speed = field(first, "speed")
        if not (close(speed[0], 0.3) and close(speed[1], 0.5) and speed[2] == 0.0):
            fail("speed {}".format(speed))
        # The bonded pair: overlap-only cohesion F_L,cg = 0.05 N on each, one contact each.
        coh = field(first, "cohesive_force")
        if not (close(coh[0], 0.05) and close(coh[1], 0.05) and coh[2] == 0.0):
            fail("cohesive_force {}".format(coh))
        contacts = field(first, "contacts")
        if list(contacts) != [1, 1, 0]:
            fail("contacts {}".format(list(contacts)))
        if list(field(first, "coal")) != [0, 0, 0] or list(field(first, "id")) != [0, 1, 2]:
            fail("coal/id")
        # The silo: 48 quads for the cone and 48 for the cylinder, 0.951 m high, 0.468 m wide.
        silo = read(os.path.join(d, "silo.vtp"))
        if silo.GetNumberOfPolys() != 96:
            fail("silo polygons {}".format(silo.GetNumberOfPolys()))
        b = silo.GetBounds()
        if not (close(b[4], 0.0) and close(b[5], 0.951) and close(b[1], 0.234)):
            fail("silo bounds {}".format(b))
        area = 0.0
        props = vtk.vtkMassProperties()
        tri = vtk.vtkTriangleFilter()
        tri.SetInputData(silo)
        props.SetInputConnection(tri.GetOutputPort())
        props.Update()
        area = props.GetSurfaceArea()
        # Lateral areas: cone pi (r1 + r2) slant, cylinder 2 pi R h (polygon: slightly less).
        r1, r2, h1, h2 = 0.025, 0.234, 0.633, 0.318
        exact = math.pi * (r1 + r2) * math.hypot(r2 - r1, h1) + 2 * math.pi * r2 * h2
        if abs(area - exact) / exact > 0.005:
            fail("silo area {} vs {}".format(area, exact))
    print("vtk readback: OK")


if __name__ == "__main__":
    main()
