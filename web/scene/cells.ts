/**
 * Cells drawn straight from the trace's points: the Int32Array the worker
 * transferred becomes the GPU buffer as it is (an integer attribute read by
 * the shaders below), never converted or copied per cell. A cell is the unit
 * cube centered on an integer grid point; only its first 3 coordinates are
 * drawn (a 2-axis point has z = 0).
 *
 * Two drawings of a buffer of cells:
 * - cubes: one instanced box per cell, shaded by a fixed light; the number
 *   drawn (instanceCount) scrubs from the start of the buffer;
 * - points: one square point per cell, sized like the cell on screen (never
 *   under 2 pixels); any range of cells can be drawn (drawRange), at one
 *   vertex each: the lighter drawing of long paths (voxel-path.ts).
 */
import * as THREE from 'three';

/** Cells from this many on are drawn as points rather than cubes (see README, "The page"), where a GPU draws. */
const LIGHT_DRAWING_CELLS = 100_000;

/**
 * The same where WebGL draws on the CPU. There a frame of the G-code
 * bench's program at 1 step/mm, 71,493 cells as cubes, took 1.5 s (SwiftShader,
 * the project's 2-core test machine), and the main thread waits for every
 * frame, so each step froze the page; drawn as points with the cubes near
 * the current cell, 0.19 s.
 */
const SOFTWARE_LIGHT_DRAWING_CELLS = 10_000;

/** Cells from this many on are drawn as points on this page's WebGL. */
export function lightDrawingCells(): number {
  return softwareRenderer() ? SOFTWARE_LIGHT_DRAWING_CELLS : LIGHT_DRAWING_CELLS;
}

/** Whether WebGL draws on the CPU, found once per page by softwareRenderer(). */
let software: boolean | undefined;

/**
 * True when WebGL draws on the CPU (SwiftShader, llvmpipe), as in headless
 * Chromium or on a machine without a usable GPU. There multisampling roughly
 * doubles the time of every frame (a long G-code program's frame: about
 * 220 ms with it, 120 ms without, on the project's 2-core test machine),
 * and the main thread waits for each frame, so the view is drawn without
 * antialiasing: jagged edges, but a page that answers in half the time.
 */
export function softwareRenderer(): boolean {
  if (software === undefined) {
    const gl = document.createElement('canvas').getContext('webgl2');
    const info = gl?.getExtension('WEBGL_debug_renderer_info');
    const name = gl ? String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER)) : '';
    gl?.getExtension('WEBGL_lose_context')?.loseContext();
    software = /swiftshader|llvmpipe|software/i.test(name);
  }
  return software;
}

/** A colour as the shaders want it: sRGB components, since these raw shaders skip three's colour management. */
function srgb(hex: string): THREE.Vector3 {
  const c = new THREE.Color(hex);
  c.convertLinearToSRGB();
  return new THREE.Vector3(c.r, c.g, c.b);
}

/**
 * The cells' coordinates as a GPU attribute over `points` (stride `dims`),
 * reading the first min(dims, 3) coordinates of each row.
 */
function cellAttribute(points: Int32Array, dims: number, instanced: boolean): THREE.BufferAttribute | THREE.InterleavedBufferAttribute {
  if (dims <= 3) return instanced ? new THREE.InstancedBufferAttribute(points, dims) : new THREE.BufferAttribute(points, dims);
  const buffer = instanced ? new THREE.InstancedInterleavedBuffer(points, dims) : new THREE.InterleavedBuffer(points, dims);
  return new THREE.InterleavedBufferAttribute(buffer, 3, 0);
}

/**
 * What every cell vertex shader starts with: the precisions and the
 * uniforms three.js and the material set (RawShaderMaterial adds none).
 */
const VERTEX_PREAMBLE = /* glsl */ `
precision highp float;
precision highp int;
uniform mat4 modelViewMatrix;
uniform mat4 projectionMatrix;
uniform float cellSize;
uniform float halfHeightPx;
uniform ivec3 origin;
out float shade;`;

/**
 * Where a vertex of the unit cube `position` lies in the cell `cell`: the
 * cube drawn cellSize wide about the cell's center. The cell is taken from
 * the origin in integers, exactly, before it becomes a float (see
 * setCellOrigin).
 */
const CELL_CORNER = /* glsl */ `
in vec3 position;
in ivec3 cell;
vec4 cellCorner() {
  return projectionMatrix * modelViewMatrix * vec4(position * cellSize + vec3(cell - origin), 1.0);
}`;

const CUBE_VERTEX = /* glsl */ `${VERTEX_PREAMBLE}${CELL_CORNER}
in vec3 normal;
void main() {
  // Lit from front-left-above, so the three visible faces of a cell differ in shade.
  vec3 light = normalize(vec3(-0.7, -1.1, 1.6));
  shade = 0.62 + 0.38 * max(dot(normal, light), 0.0);
  gl_Position = cellCorner();
}`;

const POINT_VERTEX = /* glsl */ `${VERTEX_PREAMBLE}
in ivec3 position;
void main() {
  shade = 1.0;
  vec4 eye = modelViewMatrix * vec4(vec3(position - origin), 1.0);
  gl_Position = projectionMatrix * eye;
  // A perspective projection has -1 in its third column's last row; there a
  // cell shrinks with distance, in an orthographic one it does not.
  float perspective = projectionMatrix[2][3] == -1.0 ? 1.0 / max(-eye.z, 1e-6) : 1.0;
  gl_PointSize = clamp(cellSize * projectionMatrix[1][1] * halfHeightPx * perspective, 2.0, 64.0);
}`;

/** A cube's 12 edges per cell, unshaded: the outline of a highlighted cell, in its colour exactly. */
const EDGE_VERTEX = /* glsl */ `${VERTEX_PREAMBLE}${CELL_CORNER}
void main() {
  shade = 1.0;
  gl_Position = cellCorner();
}`;

const FRAGMENT = /* glsl */ `
precision highp float;
uniform vec3 colour;
uniform float opacity;
in float shade;
out vec4 fragColour;
void main() {
  fragColour = vec4(colour * shade, opacity);
}`;

export interface CellStyle {
  colour: string;
  /** Drawn edge of a cube (or point), grid units: a little under 1 keeps neighbours apart. */
  cellSize: number;
  /** 1 opaque; below 1 drawn blended, without writing depth, after opaque things. */
  opacity: number;
  /** Cubes only: each cube's edges drawn too, opaque, in the colour itself (a highlight reads in its legend colour over whatever it surrounds). */
  outline?: boolean;
  /**
   * Drawn over everything drawn before it, depth or not, after the blended
   * cells: the second path of an overlaid comparison, whose smaller cells
   * sit inside the first path's.
   */
  onTop?: boolean;
}

/** Draw order of cells drawn on top: after blended cells (1), before the ideal path (2), which stays over them. */
const ON_TOP_ORDER = 1.5;

/** Uniforms shared by every cell drawing; halfHeightPx is updated on resize, origin by setCellOrigin. */
export const cellUniforms = { halfHeightPx: { value: 300 }, origin: { value: new THREE.Vector3() } };

/** Every cell drawing not yet disposed: each is placed at the origin. */
const live = new Set<Cells>();

/**
 * Draws every cell from the grid point `origin` (whole numbers), which the
 * view sets before each frame to the point it looks at. A WebGL float has
 * 24 bits: the cell 1,073,741,801 as a float is 1,073,741,824, and even a
 * cell 1,500,000 from the one the camera looks at came out a tenth of a
 * cell off, its cube skewed. So the shaders take each cell from the origin
 * in integers, exactly, and every drawing sits at the origin, whose
 * distance from the camera the view's matrices (doubles, in JavaScript)
 * take off before WebGL sees a float: near the camera every number the
 * GPU rounds is small.
 */
export function setCellOrigin(origin: THREE.Vector3): void {
  if (origin.equals(cellUniforms.origin.value)) return;
  cellUniforms.origin.value.copy(origin);
  for (const cells of live) cells.placeAtOrigin();
}

function material(style: CellStyle, vertexShader: string): THREE.RawShaderMaterial {
  const transparent = style.opacity < 1;
  return new THREE.RawShaderMaterial({
    glslVersion: THREE.GLSL3,
    vertexShader,
    fragmentShader: FRAGMENT,
    uniforms: {
      colour: { value: srgb(style.colour) },
      opacity: { value: style.opacity },
      cellSize: { value: style.cellSize },
      halfHeightPx: cellUniforms.halfHeightPx,
      origin: cellUniforms.origin,
    },
    transparent,
    depthWrite: !transparent && !style.onTop,
    depthTest: !style.onTop,
  });
}

/** Box vertices and normals, shared by every cube drawing, and its edges, by every outline. */
const UNIT_BOX = new THREE.BoxGeometry(1, 1, 1);
const UNIT_EDGES = new THREE.EdgesGeometry(UNIT_BOX);

/**
 * A run of cells, drawn from the start of `points` (cubes) or over any
 * range (points). `light` picks the drawing: points when true.
 */
export class Cells extends THREE.Group {
  readonly #object: THREE.Mesh | THREE.Points;
  readonly #geometry: THREE.BufferGeometry;
  readonly #material: THREE.RawShaderMaterial;
  /** The cubes' edges, when outlined. */
  readonly #edges: THREE.LineSegments<THREE.InstancedBufferGeometry, THREE.RawShaderMaterial> | undefined;
  readonly light: boolean;
  /** How many cells `points` holds. */
  readonly count: number;
  /** The cells' box, grid units. */
  readonly #bounds: THREE.Box3;

  /** `attribute` lets several drawings share one GPU buffer (see `attribute`); `bounds` frames culling. */
  constructor(points: Int32Array, dims: number, style: CellStyle, light: boolean, bounds: THREE.Box3, attribute?: THREE.BufferAttribute | THREE.InterleavedBufferAttribute) {
    super();
    this.light = light;
    this.count = points.length / dims;
    this.#bounds = bounds.clone();
    const cells = attribute ?? cellAttribute(points, dims, !light);
    if (light) {
      this.#geometry = new THREE.BufferGeometry();
      this.#geometry.setAttribute('position', cells);
      this.#material = material(style, POINT_VERTEX);
      this.#object = new THREE.Points(this.#geometry, this.#material);
    } else {
      const geometry = new THREE.InstancedBufferGeometry();
      geometry.setIndex(UNIT_BOX.index);
      geometry.setAttribute('position', UNIT_BOX.getAttribute('position'));
      geometry.setAttribute('normal', UNIT_BOX.getAttribute('normal'));
      geometry.setAttribute('cell', cells);
      geometry.instanceCount = this.count;
      this.#geometry = geometry;
      this.#material = material(style, CUBE_VERTEX);
      this.#object = new THREE.Mesh(this.#geometry, this.#material);
      if (style.outline) {
        const edges = new THREE.InstancedBufferGeometry();
        edges.setAttribute('position', UNIT_EDGES.getAttribute('position'));
        edges.setAttribute('cell', cells);
        edges.instanceCount = this.count;
        this.#edges = new THREE.LineSegments(edges, material({ ...style, opacity: 1 }, EDGE_VERTEX));
        this.add(this.#edges);
      }
    }
    // Faint cells blend over what is behind them, so they come after the opaque ones.
    this.#object.renderOrder = style.onTop ? ON_TOP_ORDER : style.opacity < 1 ? 1 : 0;
    this.add(this.#object);
    live.add(this);
    this.placeAtOrigin();
  }

  /**
   * At the cells' origin (setCellOrigin), with the box three culls by
   * taken from it too: from the path's box, not from a scan of a million
   * cells.
   */
  placeAtOrigin(): void {
    const origin = cellUniforms.origin.value;
    this.position.copy(origin);
    const box = this.#bounds.clone().translate(origin.clone().negate());
    for (const geometry of [this.#geometry, this.#edges?.geometry]) {
      if (!geometry) continue;
      geometry.boundingBox = box.clone();
      geometry.boundingSphere = box.getBoundingSphere(new THREE.Sphere());
    }
  }

  /** The GPU attribute, to share with another drawing of the same cells. */
  get attribute(): THREE.BufferAttribute | THREE.InterleavedBufferAttribute {
    return this.#geometry.getAttribute(this.light ? 'position' : 'cell');
  }

  /** Draws cells first..first + count - 1; cubes always start at 0. */
  setRange(first: number, count: number): void {
    if (this.light) this.#geometry.setDrawRange(first, count);
    else (this.#geometry as THREE.InstancedBufferGeometry).instanceCount = count;
    this.#object.visible = count > 0;
    if (this.#edges) {
      this.#edges.geometry.instanceCount = count;
      this.#edges.visible = count > 0;
    }
  }

  dispose(): void {
    live.delete(this);
    // The box's own buffers are shared (UNIT_BOX, UNIT_EDGES); only this drawing's are released.
    this.#geometry.dispose();
    this.#material.dispose();
    this.#edges?.geometry.dispose();
    this.#edges?.material.dispose();
  }
}
