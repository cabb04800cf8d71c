"""The Blender exporter (export; scripts/blender_export.py runs it), its tables (nodes,
materials, lights, settings, tangents) and the Cycles conformance fixtures (conformance;
scripts/blender_conformance.py)."""
