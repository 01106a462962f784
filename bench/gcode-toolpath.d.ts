/**
 * The part of cncjs's gcode-toolpath (3.0.0, untyped JavaScript) the G-code
 * bench calls: its README's constructor options and loadFromString.
 */
declare module 'gcode-toolpath' {
  interface ToolpathOptions {
    addLine?: (modal: unknown, v1: unknown, v2: unknown) => void;
    addArcCurve?: (modal: unknown, v1: unknown, v2: unknown, v0: unknown) => void;
  }
  export default class Toolpath {
    constructor(options?: ToolpathOptions);
    loadFromString(source: string, callback: (error: unknown, data: unknown) => void): void;
  }
}
