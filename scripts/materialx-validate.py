#!/usr/bin/env python3
"""MaterialX's own reading of .mtlx files, for tests/unit/mtlx-materialx.test.js.

  materialx-validate.py check FILE...   for each file: MaterialX's validate() (the document with MaterialX's
                                        libraries imported) and every input of its open_pbr_surface node as
                                        MaterialX parses it
  materialx-validate.py nodedef         open_pbr_surface's node definition: each input's type, default and
                                        uimin/uimax, as MaterialX reads them
  materialx-validate.py write JSON      a document MaterialX writes itself (writeToXmlString) for each material
                                        of a JSON list [{name, inputs}]

Prints JSON.
"""
import json
import sys

import MaterialX as mx


def libraries():
    lib = mx.createDocument()
    mx.loadLibraries(mx.getDefaultDataLibraryFolders(), mx.getDefaultDataSearchPath(), lib)
    return lib


def value_json(value):
    """A MaterialX value (a Value, or the Python number, bool or Color3 it unwraps to) as JSON."""
    data = value.getData() if hasattr(value, "getData") else value
    if data is None or isinstance(data, (bool, int, float, str)):
        return data
    return [float(x) for x in data.asTuple()]


def check(paths):
    lib = libraries()
    out = []
    for path in paths:
        doc = mx.createDocument()
        mx.readFromXmlFile(doc, path)
        doc.setDataLibrary(lib)  # the libraries referenced, not copied in: validate() checks the file's elements
        valid, message = doc.validate()
        nodes = [n for n in doc.getNodes() if n.getCategory() == "open_pbr_surface"]
        inputs = {}
        for node in nodes:
            for inp in node.getInputs():
                inputs[inp.getName()] = value_json(inp.getValue())
        materials = [n.getName() for n in doc.getMaterialNodes()]
        out.append({"path": path, "valid": valid, "message": message, "nodes": len(nodes),
                    "materials": materials, "inputs": inputs})
    return out


def attribute_value(inp, attribute):
    """A range attribute (uimin, uimax) parsed as the input's type, or None."""
    if not inp.hasAttribute(attribute):
        return None
    return value_json(mx.createValueFromStrings(inp.getAttribute(attribute), inp.getType()))


def nodedef():
    lib = libraries()
    nd = lib.getNodeDef("ND_open_pbr_surface_surfaceshader")
    inputs = {}
    for inp in nd.getActiveInputs():
        inputs[inp.getName()] = {
            "type": inp.getType(),
            "value": value_json(inp.getValue()),
            "uimin": attribute_value(inp, "uimin"),
            "uimax": attribute_value(inp, "uimax"),
            "defaultgeomprop": inp.getAttribute("defaultgeomprop") or None,
        }
    return {"version": nd.getVersionString(), "inputs": inputs}


def write(path):
    lib = libraries()
    with open(path, encoding="utf-8") as f:
        materials = json.load(f)
    out = []
    for material in materials:
        doc = mx.createDocument()
        doc.importLibrary(lib)
        node = doc.addNode("open_pbr_surface", material["name"] + "_shader", "surfaceshader")
        for name, value in material["inputs"].items():
            kind = node.getNodeDef().getActiveInput(name).getType()
            node.setInputValue(name, mx.Color3(*value) if kind == "color3" else float(value))
        doc.addMaterialNode(material["name"], node)
        options = mx.XmlWriteOptions()
        options.writeXIncludeEnable = False
        options.elementPredicate = lambda elem: not elem.hasSourceUri()
        out.append({"name": material["name"], "text": mx.writeToXmlString(doc, options)})
    return out


def main():
    command = sys.argv[1] if len(sys.argv) > 1 else ""
    if command == "check":
        result = check(sys.argv[2:])
    elif command == "nodedef":
        result = nodedef()
    elif command == "write" and len(sys.argv) == 3:
        result = write(sys.argv[2])
    else:
        raise SystemExit(__doc__)
    json.dump(result, sys.stdout)


if __name__ == "__main__":
    main()
