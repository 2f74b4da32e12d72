#!/usr/bin/env python3
"""MaterialX's own GLSL ES 3.00 for OpenPBR Surface, for the comparison in tests/browser/materialx.test.js.

Reads a JSON list of materials ([{"name": ..., "inputs": {"base_color": [r, g, b], "specular_roughness": 0.3, ...}}],
OpenPBR Surface's input names), puts each in a MaterialX document as one open_pbr_surface node with constant inputs,
validates the document, and has MaterialX's EsslShaderGenerator write the shader of that node from the
specification's own node graph (libraries/bxdf/open_pbr_surface.mtlx, shipped with the `materialx` package):
one directional light (the light loop's u_lightData[0], type 1), no environment (SPECULAR_ENVIRONMENT_NONE: the
indirect part is zero), no shadow map, no ambient occlusion, linear output (no sRGB encoding).

Writes JSON to stdout (or --out): {"version", "lightType", "materials": [{"name", "fragment", "uniforms"}]}, where
`uniforms` holds every public uniform MaterialX gives the node (name -> number, list or bool): the material's own
values and MaterialX's defaults for the inputs it leaves out. The inputs become uniforms, so every material's
fragment shader is the same text; it is written once per material all the same, as generated.

Usage: materialx-shaders.py MATERIALS.json [--out FILE]
"""
import argparse
import json
import sys

import MaterialX as mx
import MaterialX.PyMaterialXGenGlsl as mx_gen_glsl
import MaterialX.PyMaterialXGenShader as mx_gen_shader

LIGHT_TYPE = 1  # the id the directional light is bound to: u_lightData[i].type == 1 selects it


def load_libraries():
    """MaterialX's standard libraries (with OpenPBR's node graph and the light nodes), as installed by pip."""
    libraries = mx.createDocument()
    mx.loadLibraries(mx.getDefaultDataLibraryFolders(), mx.getDefaultDataSearchPath(), libraries)
    return libraries


def set_input(node, name, value):
    """One constant input, typed by the node definition (a colour, a vector or a float)."""
    nodedef_input = node.getNodeDef().getActiveInput(name)
    if nodedef_input is None:
        raise SystemExit(f"open_pbr_surface has no input named {name!r}")
    kind = nodedef_input.getType()
    if kind == "color3":
        node.setInputValue(name, mx.Color3(*value))
    elif kind == "vector3":
        node.setInputValue(name, mx.Vector3(*value))
    elif kind == "boolean":
        node.setInputValue(name, bool(value))
    elif kind == "float":
        node.setInputValue(name, float(value))
    else:
        raise SystemExit(f"input {name!r} has type {kind}, which this script does not set")


def material_document(libraries, material):
    """A document with one open_pbr_surface node (the material's constant inputs) and its surface material."""
    doc = mx.createDocument()
    doc.importLibrary(libraries)
    shader = doc.addNode("open_pbr_surface", "openpbr_surface", "surfaceshader")
    for name, value in material["inputs"].items():
        set_input(shader, name, value)
    doc.addMaterialNode("openpbr_material", shader)
    valid, message = doc.validate()
    if not valid:
        raise SystemExit(f"{material['name']}: MaterialX refuses the document: {message}")
    return doc, shader


def generator_context(libraries):
    """The ESSL generator with one directional light and no environment."""
    generator = mx_gen_glsl.EsslShaderGenerator.create()
    context = mx_gen_shader.GenContext(generator)
    context.registerSourceCodeSearchPath(mx.getDefaultDataSearchPath())
    options = context.getOptions()
    options.hwSpecularEnvironmentMethod = mx_gen_shader.HwSpecularEnvironmentMethod.SPECULAR_ENVIRONMENT_NONE
    options.hwMaxActiveLightSources = 1
    options.hwShadowMap = False
    options.hwAmbientOcclusion = False
    options.hwSrgbEncodeOutput = False
    options.shaderInterfaceType = mx_gen_shader.ShaderInterfaceType.SHADER_INTERFACE_COMPLETE
    mx_gen_shader.HwShaderGenerator.bindLightShader(libraries.getNodeDef("ND_directional_light"), LIGHT_TYPE, context)
    return generator, context


def uniform_value(value):
    """A uniform's default as JSON: a number, a bool or a list of numbers."""
    data = value.getData()
    if isinstance(data, (bool, int, float)):
        return data
    return [float(x) for x in data]


def public_uniforms(shader):
    """The node's inputs as MaterialX passes them to the shader (the public uniform block) with their values."""
    block = shader.getStage(mx_gen_shader.PIXEL_STAGE).getUniformBlock(mx_gen_shader.HW_PUBLIC_UNIFORMS)
    uniforms = {}
    for i in range(block.size()):
        port = block[i]
        if port.getValue() is not None:
            uniforms[port.getVariable()] = uniform_value(port.getValue())
    return uniforms


def declare_missing_uniforms(fragment):
    """MaterialX 1.39.5 with SPECULAR_ENVIRONMENT_NONE leaves out the declaration of u_refractionTwoSided, which its
    transmission code (mx_transmission_refract.glsl) still reads, and the shader does not compile. Declared here
    (left false: single-sided); it matters only for transmission, which no material compared here has."""
    name = "u_refractionTwoSided"
    if name in fragment and f"uniform bool {name};" not in fragment:
        marker = "// Uniform block: PrivateUniforms\n"
        if marker not in fragment:
            raise SystemExit("the generated shader has no private uniform block to declare u_refractionTwoSided in")
        fragment = fragment.replace(marker, f"{marker}uniform bool {name};\n", 1)
    return fragment


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("materials", help="JSON list of {name, inputs}")
    parser.add_argument("--out", help="write the JSON here (default: stdout)")
    args = parser.parse_args()
    with open(args.materials, encoding="utf-8") as f:
        materials = json.load(f)
    libraries = load_libraries()
    generator, context = generator_context(libraries)
    out = {"version": mx.getVersionString(), "lightType": LIGHT_TYPE, "materials": []}
    for material in materials:
        doc, node = material_document(libraries, material)
        shader = generator.generate(material["name"], node, context)
        out["materials"].append(
            {
                "name": material["name"],
                "fragment": declare_missing_uniforms(shader.getSourceCode(mx_gen_shader.PIXEL_STAGE)),
                "uniforms": public_uniforms(shader),
            }
        )
    text = json.dumps(out)
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            f.write(text)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
