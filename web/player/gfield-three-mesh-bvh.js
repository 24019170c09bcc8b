// three-mesh-bvh (github.com/gkjohnson/three-mesh-bvh) as the player's BVH peer: the BVH a
// three.js app walks in GLSL (drei's MeshRefractionMaterial does), built in the page over the
// exported meshes (SAH, as drei builds it) and traversed by three-mesh-bvh's own GLSL
// (bvhIntersectFirstHit) where the runtime's shaders meet a mesh: shaders/lib/gpu_bvh.glsl
// declares external_bvh_hit under GF_EXTERNAL_BVH, and `glsl` defines it. Everything else of
// the frame (G-buffer, shading, paths) is the runtime's, so the methods differ only in how a ray
// meets a mesh. The page imports this module through its import map ("three",
// "three-mesh-bvh": vendor/ of an export).

import { BufferAttribute, BufferGeometry } from 'three';
import { BVHShaderGLSL, MeshBVH, MeshBVHUniformStruct, SAH } from 'three-mesh-bvh';
import { PlayerError } from './gfield-player.js';

// GpuVertex (runtime/gpu_assets.hpp): position, normal, uv, base (rgb, texture layer); 12 floats,
// 3 RGBA32F texels.
const VERTEX_FLOATS = 12;
// Texture units of each mesh (its four BVH textures and its vertices), and at most those of the
// tracing stage itself in this method (G-buffer 4, albedo, mesh textures, environment).
const UNITS_PER_MESH = 5;
const STAGE_UNITS = 7;

// GL formats of a three.js texture of three-mesh-bvh's: 32-bit float or unsigned ("RGBA32F",
// "RG32UI", ...), the ones MeshBVHUniformStruct makes of float positions and uint32 indices.
function glFormat(gl, texture) {
  const m = /^(R|RG|RGBA)32(F|UI)$/.exec(texture.internalFormat);
  if (!m) throw new PlayerError(`three-mesh-bvh: texture format ${texture.internalFormat} unexpected`);
  const integer = m[2] === 'UI';
  const format = { R: 'RED', RG: 'RG', RGBA: 'RGBA' }[m[1]] + (integer ? '_INTEGER' : '');
  return [gl[texture.internalFormat], gl[format], integer ? gl.UNSIGNED_INT : gl.FLOAT];
}

function upload(gl, width, height, [internal, format, type], data) {
  const texture = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
  gl.texImage2D(gl.TEXTURE_2D, 0, internal, width, height, 0, format, type, data);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  return texture;
}

// three-mesh-bvh's traversal with the runtime's work counters (shaders/lib/work.glsl: WORK_ADD
// counts in the counting build, else is empty): a node per bounds test, as gfield's BVH counts
// them, and a triangle per triangle test.
function countedRayFunctions() {
  let text = BVHShaderGLSL.bvh_ray_functions;
  for (const [line, counter] of [
    ['uint currNodeIndex = stack[ pointer ];', 'WORK_BVH_NODES'],
    ['uvec3 indices = uTexelFetch1D( indexAttr, i ).xyz;', 'WORK_BVH_TRIANGLES']]) {
    if (!text.includes(line))
      throw new PlayerError(`vendor/three-mesh-bvh.js: its GLSL has no "${line}" for the work counters`);
    text = text.replace(line, `${line} WORK_ADD(${counter}, 1);`);
  }
  return text;
}

/**
 * three-mesh-bvh's BVHs of the scene's meshes on `gl` (scene: loadWebScene's result). `glsl`
 * defines external_bvh_hit for the tracing stage; `bind` sets its samplers; `buildMs` is the
 * time the page spent building the BVHs.
 */
export class ThreeMeshBvh {
  constructor(gl, scene) {
    const start = performance.now();
    const used = new Set(scene.manifest.objects.map((o) => o.mesh).filter((m) => m >= 0));
    const limit = gl.getParameter(gl.MAX_TEXTURE_IMAGE_UNITS);
    if (STAGE_UNITS + UNITS_PER_MESH * used.size > limit)
      throw new PlayerError(`method=three-mesh-bvh: ${used.size} meshes need ` +
                            `${STAGE_UNITS + UNITS_PER_MESH * used.size} texture units; this ` +
                            `browser has ${limit}`);
    this.meshes = [...used].sort((a, b) => a - b).map((m) => this.#mesh(gl, scene, m));
    this.buildMs = performance.now() - start;
    this.bytes = this.meshes.reduce((sum, mesh) => sum + mesh.bytes, 0);
  }

  // Mesh m's BVH and vertices as textures; its gfield BVH root names it in the shader.
  #mesh(gl, scene, m) {
    const mesh = scene.manifest.meshes[m];
    if (mesh.vertex_bytes !== 4 * VERTEX_FLOATS)
      throw new PlayerError(`scene.json: mesh ${m} has vertices of ${mesh.vertex_bytes} bytes; ` +
                            `this player reads ${4 * VERTEX_FLOATS}`);
    const vertices = new Float32Array(scene.bytes, mesh.vertices.offset, mesh.vertices.bytes / 4);
    const count = vertices.length / VERTEX_FLOATS;
    const positions = new Float32Array(3 * count);
    for (let i = 0; i < count; i++)
      positions.set(vertices.subarray(i * VERTEX_FLOATS, i * VERTEX_FLOATS + 3), 3 * i);
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(positions, 3));
    // A copy: the build reorders the index in place, and the export's bytes stay as they are.
    geometry.setIndex(new BufferAttribute(
        new Uint32Array(scene.bytes, mesh.indices.offset, mesh.index_count).slice(), 1));
    const struct = new MeshBVHUniformStruct();
    struct.updateFrom(new MeshBVH(geometry, { strategy: SAH }));
    const textures = {};
    let bytes = 0;
    for (const name of ['index', 'position', 'bvhBounds', 'bvhContents']) {
      const t = struct[name];
      textures[name] = upload(gl, t.image.width, t.image.height, glFormat(gl, t), t.image.data);
      bytes += t.image.data.byteLength;
    }
    // The vertices as the runtime's rasteriser reads them: 3 texels each, rows of 4096.
    const texels = 3 * count, width = Math.min(texels, 4096), height = Math.ceil(texels / width);
    const padded = new Float32Array(4 * width * height);
    padded.set(vertices);
    textures.vertices = upload(gl, width, height, [gl.RGBA32F, gl.RGBA, gl.FLOAT], padded);
    bytes += padded.byteLength;
    struct.dispose();
    return { index: m, root: mesh.bvh_root, textures, bytes };
  }

  /** The definition of external_bvh_hit (and three-mesh-bvh's GLSL it calls). */
  get glsl() {
    // Plain samplers, not three-mesh-bvh's BVH struct: with a struct of samplers SwiftShader
    // did not finish drawing this stage (minutes at 32 x 32), so the stage calls the function
    // that the struct's macro bvhIntersectFirstHit expands to.
    const names = (m) => ['position', 'index', 'bvhBounds', 'bvhContents'].map((t) => `u_tmb_${t}_${m.index}`);
    const uniforms = this.meshes.map((m) => {
      const [position, index, bounds, contents] = names(m);
      return `uniform highp usampler2D ${index};\nuniform highp sampler2D ${position};\n` +
             `uniform highp sampler2D ${bounds};\nuniform highp usampler2D ${contents};\n` +
             `uniform highp sampler2D u_tmb_vertices_${m.index};\n`;
    });
    const cases = this.meshes.map((m) => `
  if (root == ${m.root}) {
    if (_bvhIntersectFirstHit(${names(m).join(', ')}, start, d, face, normal, bary, side, dist) &&
        t_min + dist <= t_max)
      return tmb_shade(u_tmb_vertices_${m.index}, face, bary, t_min + dist, o, d);
    return miss;
  }`);
    return `
// three-mesh-bvh's GLSL (BVHShaderGLSL), which also declares an isampler2D function
precision highp isampler2D;
${BVHShaderGLSL.common_functions}
${countedRayFunctions()}
${uniforms.join('')}
// The hit on face's corners (vertex indices) at barycentrics bary, shaded as bvh_mesh_hit
// shades its hits: interpolated normal, uv and base colour (times the mesh's texture).
BvhMeshHit tmb_shade(highp sampler2D vertices, uvec4 face, vec3 bary, float t, vec3 o, vec3 d) {
  BvhMeshHit m;
  m.hit = true;
  m.t = t;
  m.position = o + t * d;
  vec3 normal = vec3(0.0f);
  vec2 uv = vec2(0.0f);
  vec3 base = vec3(0.0f);
  for (int c = 0; c < 3; c++) {
    uint v = 3u * face[c];
    vec4 pn = texelFetch1D(vertices, v);
    vec4 nuv = texelFetch1D(vertices, v + 1u);
    normal += bary[c] * vec3(pn.w, nuv.xy);
    uv += bary[c] * nuv.zw;
    base += bary[c] * texelFetch1D(vertices, v + 2u).rgb;
  }
  float layer = texelFetch1D(vertices, 3u * face.x + 2u).w;
  m.normal = normalize(normal);
  m.uv = uv;
  m.base_color = layer < -0.5f ? base
                               : base * textureLod(u_mesh_textures, vec3(uv, layer), 0.0f).rgb;
  return m;
}

// three-mesh-bvh has no t_min: the ray starts there.
BvhMeshHit external_bvh_hit(int root, vec3 o, vec3 d, float t_min, float t_max) {
  BvhMeshHit miss;
  miss.hit = false;
  vec3 start = o + t_min * d;
  uvec4 face = uvec4(0u);
  vec3 normal = vec3(0.0f), bary = vec3(0.0f);
  float side = 0.0f, dist = 0.0f;
${cases.join('')}
  return miss;
}
`;
  }

  /**
   * Binds the BVHs' textures from texture unit `unit` on for p ({ program, uniforms: name ->
   * location }); returns the next free unit.
   */
  bind(gl, p, unit) {
    for (const m of this.meshes) {
      for (const texture of ['index', 'position', 'bvhBounds', 'bvhContents', 'vertices']) {
        const name = `u_tmb_${texture}_${m.index}`;
        if (!p.uniforms.has(name)) continue;
        gl.activeTexture(gl.TEXTURE0 + unit);
        gl.bindTexture(gl.TEXTURE_2D, m.textures[texture]);
        gl.uniform1i(p.uniforms.get(name), unit++);
      }
    }
    return unit;
  }
}
