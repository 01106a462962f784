// cncjs's gcode-toolpath 3.0.0 ships no types: the part of its Toolpath class
// the G-code bench calls, as its dist/cjs/Toolpath.js has it.
declare module 'gcode-toolpath' {
  interface Vector3 {
    x: number;
    y: number;
    z: number;
  }
  interface ToolpathOptions {
    /** Called for every straight move (G0, G1) with the modal state, its start and its end. */
    addLine?: (modal: Record<string, unknown>, v1: Vector3, v2: Vector3) => void;
    /** Called for every arc (G2, G3) with its start, end and center. */
    addArcCurve?: (modal: Record<string, unknown>, v1: Vector3, v2: Vector3, v0: Vector3) => void;
  }
  export default class Toolpath {
    constructor(options?: ToolpathOptions);
    /** Parses and interprets a whole program, calling the callbacks as it goes. */
    loadFromStringSync(source: string): unknown;
  }
}
