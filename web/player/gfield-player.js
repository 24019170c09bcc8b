// The gfield web player (docs/web.md): draws a scene exported by `gfield-view SCENE --export-web
// DIR` with geometry fields in WebGL2, as gfield-view's field method does: a G-buffer of first
// hits (shaders/gbuffer.vert, gbuffer.frag), the tracing pass (field_trace.frag) and the sRGB
// presentation (present.frag), the shaders being the runtime's own in GLSL ES 3.00
// (runtime/glsl_es.hpp). The scene's bytes are the runtime's GPU buffers and textures.

/** The layout version this player reads (scene.json "version"; runtime/web_export.hpp). */
export const WEB_SCENE_VERSION = 1;

/**
 * How rays meet meshes: a geometry-field lookup, gfield's BVH of the mesh (exact), or
 * three-mesh-bvh's (exact; set FieldRenderer.externalBvh first: gfield-three-mesh-bvh.js).
 */
export const METHODS = ['field', 'bvh', 'three-mesh-bvh'];

/** Lookup modes of the field (the contract's GF_MODE_*). */
export const LOOKUP_MODES = { nearest: 0, linear: 1, refined: 2 };

/** The contract's work counters (WORK_*, shaders/lib/work.glsl) in their order. */
export const WORK_COUNTERS = ['lookups', 'field_fetches', 'image_fetches', 'newton_steps',
                              'bvh_traversals', 'bvh_nodes', 'bvh_triangles', 'rays'];

// The contract's WEB_MAX_OBJECTS, WEB_MAX_LIGHTS (shaders/lib/contract.glsl): the uniform
// blocks' declared lengths; std140 sizes of GpuObject and GpuLight in bytes.
const MAX_OBJECTS = 48;
// The contract's SCENE_CACHED_ENTRIES: scenes of at most this many objects trace with
// GF_CACHED_ENTRIES (shaders/lib/scene.glsl), as gfield-view's field method.
const CACHED_ENTRIES = 16;
const MAX_LIGHTS = 16;
const OBJECT_BYTES = 320;
const LIGHT_BYTES = 48;
// Textures of rows of WEB_TEXEL_ROW texels (2D; the others are 2D arrays).
const ROW_TEXTURES = ['field_words', 'bvh_nodes', 'bvh_triangles', 'bvh_shading'];

// A framebuffer of width x height: the textures `shared` (owned elsewhere), then new ones of
// `formats`, as colour attachments in that order, and a depth buffer with `depth`. Returns
// { fbo, textures (all attachments), owned (the new textures), depth (renderbuffer or null) }.
function makeTarget(gl, width, height, formats, shared, depth) {
  const fbo = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
  const owned = formats.map((format) => {
    const t = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.texStorage2D(gl.TEXTURE_2D, 1, format, width, height);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    return t;
  });
  const textures = [...shared, ...owned];
  textures.forEach((t, k) =>
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + k, gl.TEXTURE_2D, t, 0));
  let rb = null;
  if (depth) {
    rb = gl.createRenderbuffer();
    gl.bindRenderbuffer(gl.RENDERBUFFER, rb);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT32F, width, height);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, rb);
  }
  gl.drawBuffers(textures.map((_, k) => gl.COLOR_ATTACHMENT0 + k));
  if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE)
    throw new PlayerError('this browser cannot render to RGBA32F and RGBA32UI targets');
  return { fbo, textures, owned, depth: rb };
}

function deleteTarget(gl, target) {
  gl.deleteFramebuffer(target.fbo);
  target.owned.forEach((t) => gl.deleteTexture(t));
  if (target.depth) gl.deleteRenderbuffer(target.depth);
}

// The depth of the G-buffer's first hits as a host app's camera projects them (render's
// options.viewProjection), so that the app's own objects are drawn in depth with gfield's; no
// colour is written, and pixels without a hit keep the cleared depth.
const DEPTH_FRAG = `#version 300 es
precision highp float;
uniform highp sampler2D u_g_position;  // world position, w: first hit object (-1: none)
uniform mat4 u_host_view_projection;
out vec4 o_color;
void main() {
  vec4 p = texelFetch(u_g_position, ivec2(gl_FragCoord.xy), 0);
  if (p.w < 0.0) discard;
  vec4 clip = u_host_view_projection * vec4(p.xyz, 1.0);
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
  o_color = vec4(0.0);
}
`;

/** An error the page shows as it is: one line naming the file and what is wrong. */
export class PlayerError extends Error {}

async function fetchOk(base, file) {
  let response;
  try {
    response = await fetch(new URL(file, base));
  } catch (e) {
    throw new PlayerError(`${file}: cannot be fetched (${e.message})`);
  }
  if (!response.ok) throw new PlayerError(`${file}: cannot be fetched (HTTP ${response.status})`);
  return response;
}

// The stages of an export's shaders/ folder.
const STAGES = ['fullscreen.vert', 'gbuffer.vert', 'gbuffer.frag', 'field_trace.frag', 'present.frag'];

async function fetchManifest(base) {
  const manifestText = await (await fetchOk(base, 'scene.json')).text();
  let manifest;
  try {
    manifest = JSON.parse(manifestText);
  } catch (e) {
    throw new PlayerError(`scene.json: not JSON (${e.message})`);
  }
  if (manifest.format !== 'gfield-web')
    throw new PlayerError('scene.json: not a gfield web scene (format is not "gfield-web")');
  if (manifest.version !== WEB_SCENE_VERSION)
    throw new PlayerError(`scene.json: layout version ${manifest.version}; this player reads ` +
                          `version ${WEB_SCENE_VERSION} (export the scene again)`);
  return manifest;
}

// The manifest's scene.bin.gz, unpacked: an ArrayBuffer of manifest.bin.bytes.
async function fetchBytes(base, manifest) {
  const file = manifest.bin.file;
  const packed = (await fetchOk(base, file)).body.pipeThrough(new DecompressionStream('gzip'));
  let bytes;
  try {
    bytes = await new Response(packed).arrayBuffer();
  } catch (e) {
    throw new PlayerError(`${file}: damaged or truncated (${e.message})`);
  }
  if (bytes.byteLength !== manifest.bin.bytes)
    throw new PlayerError(`${file}: holds ${bytes.byteLength} bytes, scene.json says ` +
                          `${manifest.bin.bytes} (truncated, or from another export)`);
  return bytes;
}

/**
 * Reads DIR/scene.json and starts reading DIR/scene.bin.gz (a URL of the folder, ending in "/"):
 * resolves, once the manifest and the stages' GLSL ES texts (by file name) are in, to
 * { manifest, shaders, bytes }, bytes being a promise of scene.bin.gz unpacked (an ArrayBuffer of
 * manifest.bin.bytes) that is still downloading.
 */
export async function fetchWebScene(base) {
  const manifest = await fetchManifest(base);
  const bytes = fetchBytes(base, manifest);
  bytes.catch(() => {});  // its failure is reported where it is awaited
  const texts = await Promise.all(STAGES.map(async (stage) =>
    (await fetchOk(base, `shaders/${stage}`)).text()));
  return { manifest, shaders: Object.fromEntries(STAGES.map((stage, k) => [stage, texts[k]])), bytes };
}

/** Reads a whole export (fetchWebScene): { manifest, shaders, bytes (an ArrayBuffer) }. */
export async function loadWebScene(base) {
  const scene = await fetchWebScene(base);
  return { ...scene, bytes: await scene.bytes };
}

/**
 * Opens the export at `base` on `gl` with `settings` (FieldRenderer.settings) as fast as it can:
 * the programs those settings draw with are compiled and their pipelines built (prepare) while
 * scene.bin.gz downloads and unpacks, and then it is uploaded. Resolves to { scene (as
 * loadWebScene's), renderer, startup: ms spent { fetch: the manifest and shaders, prepare,
 * load: waiting for the bytes after that, upload } }.
 */
export async function openWebScene(gl, base, settings = {}) {
  let time = performance.now();
  const lap = () => { const now = performance.now(), ms = now - time; time = now; return ms; };
  const scene = await fetchWebScene(base);
  const startup = { fetch: lap() };
  const renderer = new FieldRenderer(gl, { manifest: scene.manifest, shaders: scene.shaders });
  Object.assign(renderer.settings, settings);
  renderer.prepare();
  startup.prepare = lap();
  scene.bytes = await scene.bytes;
  startup.load = lap();
  renderer.upload(scene.bytes);
  startup.upload = lap();
  return { scene, renderer, startup };
}

// Column-major 4x4 matrices as glm's (GL clip space, z in [-1, 1]).
function lookAt(eye, target, up) {
  const f = normalize(sub(target, eye));
  const s = normalize(cross(f, up));
  const u = cross(s, f);
  return [s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0,
          -dot(s, eye), -dot(u, eye), dot(f, eye), 1];
}
function perspective(fovy, aspect, near, far) {
  const t = 1 / Math.tan(fovy / 2);
  return [t / aspect, 0, 0, 0, 0, t, 0, 0, 0, 0, -(far + near) / (far - near), -1,
          0, 0, -(2 * far * near) / (far - near), 0];
}
function multiply(a, b) {
  const m = new Array(16).fill(0);
  for (let c = 0; c < 4; c++)
    for (let r = 0; r < 4; r++)
      for (let k = 0; k < 4; k++) m[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
  return m;
}
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                         a[0] * b[1] - a[1] * b[0]];
const normalize = (a) => { const l = Math.hypot(a[0], a[1], a[2]); return [a[0] / l, a[1] / l, a[2] / l]; };

// runtime/gpu_scene.cpp's depth_range: near and far planes keeping every object in view.
function depthRange(eye, objects, edgeCosine) {
  let nearest = Infinity, farthest = 0, inside = false;
  for (const o of objects) {
    const [lo, hi] = o.world_bounds;
    const below = sub(lo, eye), above = sub(hi, eye);
    const out = [0, 1, 2].map((i) => Math.max(below[i], -above[i], 0));
    const toBox = Math.hypot(out[0], out[1], out[2]);
    const far = [0, 1, 2].map((i) => Math.max(Math.abs(below[i]), Math.abs(above[i])));
    farthest = Math.max(farthest, Math.hypot(far[0], far[1], far[2]));
    if (toBox > 0) nearest = Math.min(nearest, toBox);
    else inside = true;
  }
  const farPlane = Math.max(1.01 * farthest, 1e-3);
  let nearPlane = Math.min(0.5 * edgeCosine * nearest, 0.5 * farPlane);
  if (inside || nearest === Infinity) nearPlane = Math.min(nearPlane, 1e-4 * farPlane);
  return [Math.max(nearPlane, 1e-7 * farPlane), farPlane];
}

// Upload formats of the manifest's texture formats.
function textureFormat(gl, format) {
  switch (format) {
    case 'rgba32f': return [gl.RGBA32F, gl.RGBA, gl.FLOAT, Float32Array, 4];
    case 'rgba16f': return [gl.RGBA16F, gl.RGBA, gl.HALF_FLOAT, Uint16Array, 4];
    case 'rg8': return [gl.RG8, gl.RG, gl.UNSIGNED_BYTE, Uint8Array, 2];
    case 'r32ui': return [gl.R32UI, gl.RED_INTEGER, gl.UNSIGNED_INT, Uint32Array, 1];
    default: throw new PlayerError(`scene.json: unknown texture format "${format}"`);
  }
}

function checkBlock(block, bytes, what) {
  if (!block || block.offset + block.bytes > bytes.byteLength)
    throw new PlayerError(`scene.json: ${what} lies outside scene.bin.gz`);
}

/**
 * The geometry-field renderer of one exported scene on a WebGL2 context: the runtime's field
 * method. Settings: depth (reflections/refractions after the camera ray), mode (a LOOKUP_MODES
 * key), selfReflection, minWeight, maxRays. `scene` is loadWebScene's; without its bytes
 * (fetchWebScene's manifest and shaders alone) the renderer draws once they are given to upload.
 */
export class FieldRenderer {
  constructor(gl, scene) {
    this.gl = gl;
    this.manifest = scene.manifest;
    this.shaders = scene.shaders;
    this.settings = { method: 'field', depth: 10, mode: 'refined', selfReflection: true,
                      minWeight: 0.005, maxRays: 24 };
    if (!gl.getExtension('EXT_color_buffer_float'))
      throw new PlayerError('this browser cannot render to float textures (EXT_color_buffer_float)');
    gl.getExtension('OES_texture_float_linear');
    this.gbufferProgram = this.#program('gbuffer.vert', 'gbuffer.frag', '');
    this.presentProgram = this.#program('fullscreen.vert', 'present.frag', '');
    this.depthProgram = this.#program('fullscreen.vert',
                                      { name: 'gfield-player.js (its depth pass)', text: DEPTH_FRAG }, '');
    this.tracePrograms = new Map();
    this.someWithField = this.manifest.meshes.some((m) => m.field !== false);
    this.someWithoutField = this.manifest.meshes.some((m) => m.field === false);
    this.emptyVao = gl.createVertexArray();
    // The three-mesh-bvh method's BVHs: { glsl, bind(gl, program, unit) } (ThreeMeshBvh).
    this.externalBvh = null;
    if (scene.bytes) this.upload(scene.bytes);
  }

  /** Uploads the scene's bytes (an ArrayBuffer of manifest.bin.bytes); once. */
  upload(bytes) {
    const gl = this.gl, m = this.manifest;
    if (this.uploaded) throw new PlayerError('the scene is uploaded already');
    const limit = gl.getParameter(gl.MAX_TEXTURE_SIZE);
    this.textures = {};
    for (const [name, t] of Object.entries(m.textures)) {
      checkBlock(t, bytes, `texture ${name}`);
      if (t.width > limit || t.height > limit)
        throw new PlayerError(`scene.json: ${name} is ${t.width} x ${t.height} texels; this ` +
                              `browser's textures stop at ${limit}`);
      const [, , , View, channels] = textureFormat(gl, t.format);
      const data = new View(bytes, t.offset, t.width * t.height * t.layers * channels);
      this.textures[name] = this.#texture(name, t, [t.width, t.height, t.layers], data);
    }
    this.objectsBlock = this.#uniformBlock(bytes, m.blocks.objects, MAX_OBJECTS * OBJECT_BYTES, 'objects');
    this.lightsBlock = this.#uniformBlock(bytes, m.blocks.lights, MAX_LIGHTS * LIGHT_BYTES, 'lights');
    this.meshes = m.meshes.map((mesh, i) => this.#mesh(bytes, mesh, `mesh ${i}`));
    this.proxyCube = this.#mesh(bytes, m.proxy_cube, 'the proxy cube');
    this.uploaded = true;
  }

  // Texture `name` of the manifest (its entry `t`) at [width, height, layers], holding `data`
  // (a typed array of its format; null: zeros).
  #texture(name, t, [width, height, layers], data) {
    const gl = this.gl;
    const [internal, format, type] = textureFormat(gl, t.format);
    const array = !ROW_TEXTURES.includes(name);
    const target = array ? gl.TEXTURE_2D_ARRAY : gl.TEXTURE_2D;
    const texture = gl.createTexture();
    gl.bindTexture(target, texture);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    if (array) gl.texImage3D(target, 0, internal, width, height, layers, 0, format, type, data);
    else gl.texImage2D(target, 0, internal, width, height, 0, format, type, data);
    // The meshes' own textures are filtered (GL_LINEAR, GL_REPEAT); the rest read by texelFetch.
    const linear = name === 'mesh_textures';
    gl.texParameteri(target, gl.TEXTURE_MIN_FILTER, linear ? gl.LINEAR : gl.NEAREST);
    gl.texParameteri(target, gl.TEXTURE_MAG_FILTER, linear ? gl.LINEAR : gl.NEAREST);
    const wrap = linear ? gl.REPEAT : gl.CLAMP_TO_EDGE;
    gl.texParameteri(target, gl.TEXTURE_WRAP_S, wrap);
    gl.texParameteri(target, gl.TEXTURE_WRAP_T, wrap);
    return { texture, target };
  }

  /**
   * Compiles the programs the settings draw with and builds their pipelines, before upload: it
   * draws one pixel of the camera's frame with stand-ins for the scene's data (textures of 1 x 1
   * texels in the scene's formats, zero uniform blocks, one degenerate triangle per mesh).
   * Renderers build a program's pipeline at its first draw (SwiftShader about 1.6 s for the
   * tracing stage), work that can then overlap the download of scene.bin.gz. The three-mesh-bvh
   * method's tracing program is built with its BVHs, later.
   */
  prepare() {
    const gl = this.gl, m = this.manifest;
    if (this.uploaded) return;
    this.textures = Object.fromEntries(Object.entries(m.textures).map(([name, t]) =>
      [name, this.#texture(name, t, [1, 1, 1], null)]));
    const block = (size) => {
      const buffer = gl.createBuffer();
      gl.bindBuffer(gl.UNIFORM_BUFFER, buffer);
      gl.bufferData(gl.UNIFORM_BUFFER, size, gl.STATIC_DRAW);
      return buffer;
    };
    this.objectsBlock = block(MAX_OBJECTS * OBJECT_BYTES);
    this.lightsBlock = block(MAX_LIGHTS * LIGHT_BYTES);
    const zeros = new ArrayBuffer(3 * m.proxy_cube.vertex_bytes);
    const triangle = { vertex_bytes: m.proxy_cube.vertex_bytes, index_count: 3,
                       vertices: { offset: 0, bytes: zeros.byteLength }, indices: { offset: 0, bytes: 12 } };
    const standIn = this.#mesh(zeros, triangle, 'a stand-in');
    this.meshes = m.meshes.map(() => standIn);
    this.proxyCube = standIn;
    try {
      this.#targets(1, 1);
      this.#drawGbuffer(m.camera, 1, 1);
      if (this.settings.method !== 'three-mesh-bvh') this.#drawTracing(m.camera, 1, 1);
      this.#present(1, 1);
    } finally {
      Object.values(this.textures).forEach((t) => gl.deleteTexture(t.texture));
      gl.deleteBuffer(this.objectsBlock);
      gl.deleteBuffer(this.lightsBlock);
      gl.deleteVertexArray(standIn.vao);
      gl.deleteBuffer(standIn.vertices);
      gl.deleteBuffer(standIn.indices);
      this.textures = null;
      gl.bindVertexArray(null);
      gl.useProgram(null);
    }
  }

  // A uniform block's buffer, padded to the length its declaration has.
  #uniformBlock(bytes, block, size, what) {
    checkBlock(block, bytes, `the ${what} block`);
    if (block.bytes > size) throw new PlayerError(`scene.json: more ${what} than the player draws`);
    const data = new Uint8Array(size);
    data.set(new Uint8Array(bytes, block.offset, block.bytes));
    const buffer = this.gl.createBuffer();
    this.gl.bindBuffer(this.gl.UNIFORM_BUFFER, buffer);
    this.gl.bufferData(this.gl.UNIFORM_BUFFER, data, this.gl.STATIC_DRAW);
    return buffer;
  }

  // An indexed mesh of GpuVertex (position, normal, uv, base: 12 floats).
  #mesh(bytes, mesh, what) {
    const gl = this.gl;
    checkBlock(mesh.vertices, bytes, `${what}'s vertices`);
    checkBlock(mesh.indices, bytes, `${what}'s indices`);
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const vertices = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vertices);
    gl.bufferData(gl.ARRAY_BUFFER, new Uint8Array(bytes, mesh.vertices.offset, mesh.vertices.bytes),
                  gl.STATIC_DRAW);
    const stride = mesh.vertex_bytes;
    [[0, 3, 0], [1, 3, 12], [2, 2, 24], [3, 4, 32]].forEach(([location, size, offset]) => {
      gl.enableVertexAttribArray(location);
      gl.vertexAttribPointer(location, size, gl.FLOAT, false, stride, offset);
    });
    const indices = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, indices);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint8Array(bytes, mesh.indices.offset, mesh.indices.bytes),
                  gl.STATIC_DRAW);
    gl.bindVertexArray(null);
    return { vao, count: mesh.index_count, vertices, indices };
  }

  // A program of two stages (an exported stage's file name, or { name, text }), `defines` after
  // each stage's first line, `appended` after the fragment stage.
  #program(vertex, fragment, defines, appended = '') {
    const gl = this.gl;
    const program = gl.createProgram();
    for (const [stage, type] of [[vertex, gl.VERTEX_SHADER], [fragment, gl.FRAGMENT_SHADER]]) {
      const { name, text } = typeof stage === 'string'
          ? { name: `shaders/${stage}`, text: this.shaders[stage] } : stage;
      const first = text.indexOf('\n') + 1;
      const shader = gl.createShader(type);
      const tail = type === gl.FRAGMENT_SHADER ? appended : '';
      gl.shaderSource(shader, text.slice(0, first) + defines + text.slice(first) + tail);
      gl.compileShader(shader);
      if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS))
        throw new PlayerError(`${name}: does not compile: ` +
                              `${(gl.getShaderInfoLog(shader) || '').split('\n')[0]}`);
      gl.attachShader(program, shader);
    }
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS))
      throw new PlayerError(`shaders/${fragment}: does not link: ${gl.getProgramInfoLog(program)}`);
    const objects = gl.getUniformBlockIndex(program, 'Objects');
    if (objects !== gl.INVALID_INDEX) gl.uniformBlockBinding(program, objects, 0);
    const lights = gl.getUniformBlockIndex(program, 'Lights');
    if (lights !== gl.INVALID_INDEX) gl.uniformBlockBinding(program, lights, 1);
    const uniforms = new Map();
    const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS);
    for (let i = 0; i < count; i++) {
      const name = gl.getActiveUniform(program, i).name.replace(/\[0\]$/, '');
      uniforms.set(name, gl.getUniformLocation(program, name));
    }
    return { program, uniforms };
  }

  // The tracing program of the settings; `count`: its counting build (GF_COUNT_WORK).
  #traceProgram(count = false) {
    const mode = LOOKUP_MODES[this.settings.mode];
    if (mode === undefined) throw new PlayerError(`mode=${this.settings.mode}: not a lookup mode`);
    const method = this.settings.method;
    if (!METHODS.includes(method))
      throw new PlayerError(`method=${method}: expected ${METHODS.join(', ')}`);
    const external = method === 'three-mesh-bvh';
    if (external && !this.externalBvh)
      throw new PlayerError('method=three-mesh-bvh: its BVHs are not built (externalBvh)');
    // As gfield-view's field method builds its programs (--intersect field or bvh): meshes
    // exported without a field are traced by their BVH in every method.
    const byField = method === 'field' && this.someWithField;
    const byBvh = method !== 'field' || this.someWithoutField;
    const key = `${method} ${mode}${count ? ' counting' : ''}`;
    if (!this.tracePrograms.has(key))
      this.tracePrograms.set(key, this.#program('fullscreen.vert', 'field_trace.frag',
          `#define GF_TRACE_MODE ${mode}\n#define GF_FIELD_MESHES ${byField ? 1 : 0}\n` +
          `#define GF_BVH_MESHES ${byBvh ? 1 : 0}\n${external ? '#define GF_EXTERNAL_BVH 1\n' : ''}` +
          `#define GF_CACHED_ENTRIES ${this.manifest.objects.length <= CACHED_ENTRIES ? 1 : 0}\n` +
          `${count ? '#define GF_COUNT_WORK 1\n' : ''}`,
          external ? this.externalBvh.glsl : ''));
    return this.tracePrograms.get(key);
  }

  // Render targets of width x height: the G-buffer (4 RGBA32F + depth) and the frame (colour and
  // hits, RGBA32F); those of another size are deleted. countWork adds its own.
  #targets(width, height) {
    if (this.size && this.size[0] === width && this.size[1] === height) return;
    const gl = this.gl;
    for (const t of [this.gbuffer, this.frame, this.counting]) if (t) deleteTarget(gl, t);
    this.counting = null;
    const float = gl.RGBA32F;
    this.gbuffer = makeTarget(gl, width, height, [float, float, float, float], [], true);
    this.frame = makeTarget(gl, width, height, [float, float], [], false);
    this.size = [width, height];
  }

  #bindScene(p) {
    const gl = this.gl;
    gl.bindBufferBase(gl.UNIFORM_BUFFER, 0, this.objectsBlock);
    gl.bindBufferBase(gl.UNIFORM_BUFFER, 1, this.lightsBlock);
    const samplers = {
      u_gi_positions: this.textures.gi_positions, u_gi_normals: this.textures.gi_normals,
      u_fields: this.textures.fields, u_field_words: this.textures.field_words,
      u_gi_albedo: this.textures.gi_albedo, u_mesh_textures: this.textures.mesh_textures,
      u_env_images: this.textures.environment, u_bvh_nodes: this.textures.bvh_nodes,
      u_bvh_triangles: this.textures.bvh_triangles, u_bvh_shading: this.textures.bvh_shading,
    };
    let unit = 0;
    for (const [name, t] of Object.entries(samplers)) {
      if (!p.uniforms.has(name)) continue;
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(t.target, t.texture);
      gl.uniform1i(p.uniforms.get(name), unit++);
    }
    return unit;
  }

  #setSceneUniforms(p) {
    const gl = this.gl, u = this.manifest.uniforms;
    const set = (name, f) => { if (p.uniforms.has(name)) f(p.uniforms.get(name)); };
    set('u_object_count', (l) => gl.uniform1i(l, u.object_count));
    set('u_light_count', (l) => gl.uniform1i(l, u.light_count));
    set('u_ambient', (l) => gl.uniform3fv(l, u.ambient));
    set('u_scene_extent', (l) => gl.uniform1f(l, u.scene_extent));
    set('u_env_type', (l) => gl.uniform1i(l, u.env_type));
    set('u_env_color', (l) => gl.uniform3fv(l, u.env_color));
    set('u_env_intensity', (l) => gl.uniform1f(l, u.env_intensity));
  }

  #setCameraUniforms(p, camera, width, height) {
    const gl = this.gl;
    const forward = normalize(sub(camera.target, camera.position));
    const right = normalize(cross(forward, camera.up));
    const up = cross(right, forward);
    const tanHalf = Math.tan(camera.fov * Math.PI / 360);
    const set = (name, f) => { if (p.uniforms.has(name)) f(p.uniforms.get(name)); };
    set('u_camera_position', (l) => gl.uniform3fv(l, camera.position));
    set('u_camera_forward', (l) => gl.uniform3fv(l, forward));
    set('u_camera_right', (l) => gl.uniform3fv(l, right));
    set('u_camera_up', (l) => gl.uniform3fv(l, up));
    set('u_tan_half', (l) => gl.uniform2f(l, tanHalf * width / height, tanHalf));
    set('u_image_size', (l) => gl.uniform2f(l, width, height));
    set('u_jitter', (l) => gl.uniform2f(l, 0, 0));
  }

  #drawGbuffer(camera, width, height) {
    const gl = this.gl, p = this.gbufferProgram;
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.gbuffer.fbo);
    gl.viewport(0, 0, width, height);
    gl.clearBufferfv(gl.COLOR, 0, [0, 0, 0, -1]);
    for (let k = 1; k < 4; k++) gl.clearBufferfv(gl.COLOR, k, [0, 0, 0, 0]);
    gl.depthMask(true);
    gl.clearDepth(1);
    gl.clear(gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LESS);
    gl.disable(gl.CULL_FACE);
    gl.disable(gl.BLEND);
    gl.useProgram(p.program);
    this.#bindScene(p);
    // runtime/gpu_scene.cpp's camera_frustum.
    const tanHalf = Math.tan(camera.fov * Math.PI / 360);
    const sides = width / height;
    const edge = Math.atan(tanHalf * Math.sqrt(1 + sides * sides));
    const [near, far] = depthRange(camera.position, this.manifest.objects, Math.cos(edge));
    const viewProjection = multiply(perspective(camera.fov * Math.PI / 180, width / height, near, far),
                                    lookAt(camera.position, camera.target, camera.up));
    gl.uniformMatrix4fv(p.uniforms.get('u_view_projection'), false, viewProjection);
    gl.uniform3fv(p.uniforms.get('u_camera_position'), camera.position);
    this.manifest.objects.forEach((o, k) => {
      const set = (name, f) => { if (p.uniforms.has(name)) f(p.uniforms.get(name)); };
      set('u_to_world', (l) => gl.uniformMatrix4fv(l, false, o.to_world));
      set('u_to_object', (l) => gl.uniformMatrix4fv(l, false, o.to_object));
      set('u_object', (l) => gl.uniform1i(l, k));
      set('u_shape', (l) => gl.uniform1i(l, o.shape));
      set('u_shape_params', (l) => gl.uniform4fv(l, o.shape_params));
      set('u_shape_size', (l) => gl.uniform3fv(l, o.shape_size));
      set('u_proxy_half', (l) => gl.uniform3fv(l, o.proxy_half));
      const mesh = o.mesh >= 0 ? this.meshes[o.mesh] : this.proxyCube;
      gl.bindVertexArray(mesh.vao);
      gl.drawElements(gl.TRIANGLES, mesh.count, gl.UNSIGNED_INT, 0);
    });
    gl.bindVertexArray(null);
  }

  #drawTracing(camera, width, height, count = false) {
    const gl = this.gl, p = this.#traceProgram(count), s = this.settings;
    gl.bindFramebuffer(gl.FRAMEBUFFER, (count ? this.counting : this.frame).fbo);
    gl.viewport(0, 0, width, height);
    gl.disable(gl.DEPTH_TEST);
    gl.useProgram(p.program);
    let unit = this.#bindScene(p);
    ['u_g_position', 'u_g_normal', 'u_g_geometric', 'u_g_albedo'].forEach((name, k) => {
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, this.gbuffer.textures[k]);
      gl.uniform1i(p.uniforms.get(name), unit++);
    });
    if (s.method === 'three-mesh-bvh') unit = this.externalBvh.bind(gl, p, unit);
    this.#setSceneUniforms(p);
    this.#setCameraUniforms(p, camera, width, height);
    const set = (name, f) => { if (p.uniforms.has(name)) f(p.uniforms.get(name)); };
    set('u_self_reflection', (l) => gl.uniform1i(l, s.selfReflection ? 1 : 0));
    set('u_intersect_bvh', (l) => gl.uniform1i(l, s.method !== 'field' ? 1 : 0));
    set('u_max_depth', (l) => gl.uniform1i(l, s.depth));
    set('u_min_weight', (l) => gl.uniform1f(l, s.minWeight));
    set('u_max_rays', (l) => gl.uniform1i(l, s.maxRays));
    gl.bindVertexArray(this.emptyVao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  /**
   * Draws `camera` at width x height with the tracing pass's counting build (shown nowhere) and
   * returns workSummary of its counts: what `gfield-view --count-work` counts for that frame.
   */
  countWork(camera, width, height) {
    const gl = this.gl;
    if (!this.uploaded) throw new PlayerError('countWork: the scene\'s bytes are not uploaded yet');
    this.#targets(width, height);
    // The frame's colour and hits, then two RGBA32UI attachments for the counts.
    this.counting ??= makeTarget(gl, width, height, [gl.RGBA32UI, gl.RGBA32UI],
                                 this.frame.textures, false);
    this.#drawGbuffer(camera, width, height);
    this.#drawTracing(camera, width, height, true);
    const totals = Object.fromEntries(WORK_COUNTERS.map((name) => [name, 0]));
    const texels = new Uint32Array(4 * width * height);
    for (const k of [0, 1]) {
      gl.readBuffer(gl.COLOR_ATTACHMENT2 + k);
      gl.readPixels(0, 0, width, height, gl.RGBA_INTEGER, gl.UNSIGNED_INT, texels);
      for (let i = 0; i < texels.length; i++) totals[WORK_COUNTERS[4 * k + (i & 3)]] += texels[i];
    }
    gl.readBuffer(gl.COLOR_ATTACHMENT0);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return workSummary(totals);
  }

  /**
   * Draws `camera` ({position, target, up, fov in degrees}) into the default framebuffer's
   * bottom-left width x height pixels. With options.viewProjection (a host app's camera: 16
   * floats, column-major, GL clip space) it also writes the first hits' depth as that camera
   * sees them into the default framebuffer's depth buffer (all of it cleared to 1 first), so
   * that the app's objects drawn after it meet gfield's in depth.
   */
  render(camera, width, height, options = {}) {
    if (!this.uploaded) throw new PlayerError('render: the scene\'s bytes are not uploaded yet');
    this.#targets(width, height);
    this.#drawGbuffer(camera, width, height);
    this.#drawTracing(camera, width, height);
    this.#present(width, height);
    if (options.viewProjection) this.#drawDepth(options.viewProjection);
  }

  // The frame's colour, sRGB-encoded, into the default framebuffer's bottom-left pixels.
  #present(width, height) {
    const gl = this.gl;
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.viewport(0, 0, width, height);
    const p = this.presentProgram;
    gl.useProgram(p.program);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.frame.textures[0]);
    gl.uniform1i(p.uniforms.get('u_frame'), 0);
    gl.bindVertexArray(this.emptyVao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  }

  #drawDepth(viewProjection) {
    const gl = this.gl, p = this.depthProgram;
    gl.depthMask(true);
    gl.clearDepth(1);
    gl.clear(gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.ALWAYS);
    gl.colorMask(false, false, false, false);
    gl.useProgram(p.program);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.gbuffer.textures[0]);
    gl.uniform1i(p.uniforms.get('u_g_position'), 0);
    gl.uniformMatrix4fv(p.uniforms.get('u_host_view_projection'), false, viewProjection);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.colorMask(true, true, true, true);
    gl.depthFunc(gl.LESS);
    gl.disable(gl.DEPTH_TEST);
  }
}

/**
 * Work counter totals (an object keyed by WORK_COUNTERS) with the averages gfield-view
 * --count-work prints: per field lookup and per BVH traversal.
 */
export function workSummary(totals) {
  const per = (a, b) => (totals[b] > 0 ? totals[a] / totals[b] : 0);
  return {
    totals,
    per_lookup: { field_fetches: per('field_fetches', 'lookups'),
                  image_fetches: per('image_fetches', 'lookups'),
                  newton_steps: per('newton_steps', 'lookups') },
    per_traversal: { nodes: per('bvh_nodes', 'bvh_traversals'),
                     triangles: per('bvh_triangles', 'bvh_traversals') },
  };
}

/**
 * The camera `render` takes, from a three.js PerspectiveCamera (its world matrix and vertical
 * fov): gfield-player.js itself needs no three.js.
 */
export function cameraFromThree(camera) {
  camera.updateMatrixWorld();
  const m = camera.matrixWorld.elements;  // column-major: x, y, z axes, then the position
  const position = [m[12], m[13], m[14]];
  return { position, target: [m[12] - m[8], m[13] - m[9], m[14] - m[10]], up: [m[4], m[5], m[6]],
           fov: camera.fov };
}

/**
 * Draws `field` (a FieldRenderer made on `renderer.getContext()`) as three.js's `camera` sees it
 * into the whole drawing buffer of `renderer` (a THREE.WebGLRenderer), with the depth of its
 * first hits in three.js's depth buffer, resetting three.js's idea of the GL state before and
 * after. Then draw three.js objects with renderer.autoClear = false: they meet gfield's objects
 * in depth (in front of or behind them) and cover the background. gfield draws from the
 * camera's position, orientation and vertical fov at the drawing buffer's aspect: a camera with
 * zoom, a view offset or a film offset is refused, and the renderer's depth buffer must be the
 * plain one (not logarithmic or reversed).
 */
export function drawWithThree(field, renderer, camera) {
  if (camera.zoom !== 1 || camera.view?.enabled || camera.filmOffset)
    throw new PlayerError('drawWithThree: the camera has a zoom, view offset or film offset, ' +
                          'which gfield does not draw');
  const size = renderer.getDrawingBufferSize(new camera.position.constructor());
  const view = cameraFromThree(camera);  // updates camera.matrixWorldInverse too
  const viewProjection = camera.projectionMatrix.clone().multiply(camera.matrixWorldInverse);
  renderer.resetState();
  field.render(view, size.x, size.y, { viewProjection: viewProjection.elements });
  renderer.resetState();
}
