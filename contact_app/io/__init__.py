"""Mesh input besides the C++ ``.mdpa`` reader: meshes read through meshio."""

from .meshio_import import ImportMeshioModelPart, read_mesh

__all__ = ["ImportMeshioModelPart", "read_mesh"]
