"""gltf_variants.py -- glTF documents the benches derive from a scene's:
its materials with no reflection at their interface."""

import json


def lambertian_gltf(doc, path):
    """The same document with specularFactor 0 on every material, written to
    `path` (a pathlib.Path): with no metal, Lambertian surfaces of the file's
    base colours (a program without WF_HAS_SPECULAR)."""
    doc = json.loads(json.dumps(doc))
    for m in doc["materials"]:
        m.setdefault("extensions", {})["KHR_materials_specular"] = {"specularFactor": 0.0}
    used = doc.setdefault("extensionsUsed", [])
    if "KHR_materials_specular" not in used:
        used.append("KHR_materials_specular")
    path.write_text(json.dumps(doc))
