/**
 * Byte-level scanning of text mesh formats (OBJ, OFF, ASCII PLY/STL) without decoding the whole
 * file to a string: numbers are parsed straight from the bytes, which keeps million-line files fast.
 */
import { MeshFormatError } from './types.ts';

const SPACE = 0x20;
const TAB = 0x09;
const LF = 0x0a;
const VT = 0x0b;
const FF = 0x0c;
const CR = 0x0d;
const HASH = 0x23;
const PLUS = 0x2b;
const MINUS = 0x2d;
const DOT = 0x2e;
const ZERO = 0x30;
const NINE = 0x39;

/** Exact powers of ten: a mantissa below 2^53 times/divided by one of these is correctly rounded. */
const POW10 = Array.from({ length: 23 }, (_, i) => Number(`1e${i}`));
const MAX_EXACT = 2 ** 53;
const DECIMAL = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

/** Blanks separate tokens within a line: spaces, tabs, the rare VT/FF, and CR so that CRLF files read like LF ones. */
export function isBlank(b: number): boolean {
  return b === SPACE || b === TAB || b === CR || b === VT || b === FF;
}

/** Whether `b` ends a token: blank, line feed or (when the format has them) a comment. */
function isTokenEnd(b: number, hashComments: boolean): boolean {
  return isBlank(b) || b === LF || (hashComments && b === HASH);
}

/** Reads a text mesh format token by token, tracking the line number for error messages. */
export class TextScanner {
  pos: number;
  /** 1-based line number of `pos`. */
  line: number;

  constructor(
    readonly bytes: Uint8Array,
    /** Format name that starts every error message, e.g. "OBJ". */
    readonly label: string,
    /** Whether '#' starts a comment that runs to the end of the line. */
    readonly hashComments: boolean,
    start = 0,
    startLine = 1,
  ) {
    this.pos = start;
    this.line = startLine;
  }

  atEnd(): boolean {
    return this.pos >= this.bytes.length;
  }

  /** Skips blanks within the current line. */
  skipBlanks(): void {
    const { bytes } = this;
    let p = this.pos;
    while (p < bytes.length && isBlank(bytes[p])) p++;
    this.pos = p;
  }

  /** After skipping blanks: is the rest of the line empty (or a comment)? */
  atLineEnd(): boolean {
    this.skipBlanks();
    if (this.pos >= this.bytes.length) return true;
    const b = this.bytes[this.pos];
    return b === LF || (this.hashComments && b === HASH);
  }

  /** Moves to the start of the next line. */
  skipLine(): void {
    const i = this.bytes.indexOf(LF, this.pos);
    if (i < 0) {
      this.pos = this.bytes.length;
    } else {
      this.pos = i + 1;
      this.line++;
    }
  }

  /** Skips blanks, line breaks and comments up to the next token (or the end of the file). */
  skipWhitespace(): void {
    const { bytes } = this;
    for (;;) {
      this.skipBlanks();
      if (this.pos >= bytes.length) return;
      const b = bytes[this.pos];
      if (b === LF) {
        this.pos++;
        this.line++;
      } else if (this.hashComments && b === HASH) {
        this.skipLine();
      } else {
        return;
      }
    }
  }

  /** End (exclusive) of the token starting at `pos`. */
  tokenEnd(): number {
    const { bytes } = this;
    let p = this.pos;
    while (p < bytes.length && !isTokenEnd(bytes[p], this.hashComments)) p++;
    return p;
  }

  /** The token at `pos` as a string (for keywords and error messages), without consuming it. */
  peekToken(): string {
    return latin1(this.bytes, this.pos, this.tokenEnd());
  }

  /** Whether the token at `pos` is exactly `word` (ASCII bytes). */
  tokenIs(word: Uint8Array): boolean {
    const { bytes, pos } = this;
    if (pos + word.length > bytes.length) return false;
    for (let i = 0; i < word.length; i++) if (bytes[pos + i] !== word[i]) return false;
    const after = pos + word.length;
    return after === bytes.length || isTokenEnd(bytes[after], this.hashComments);
  }

  /** Consumes the token at `pos`. */
  skipToken(): void {
    this.pos = this.tokenEnd();
  }

  /**
   * Reads a number (after blanks on the current line). NaN and infinities are passed through;
   * anything else that is not a number is an error naming the line.
   */
  readNumber(): number {
    this.skipBlanks();
    const { bytes } = this;
    const start = this.pos;
    const len = bytes.length;
    let p = start;
    let negative = false;
    if (p < len && (bytes[p] === MINUS || bytes[p] === PLUS)) negative = bytes[p++] === MINUS;
    let mantissa = 0;
    let exponent = 0;
    let digits = 0;
    let b = 0;
    while (p < len && (b = bytes[p]) >= ZERO && b <= NINE) {
      mantissa = mantissa * 10 + (b - ZERO);
      digits++;
      p++;
    }
    if (p < len && bytes[p] === DOT) {
      p++;
      while (p < len && (b = bytes[p]) >= ZERO && b <= NINE) {
        mantissa = mantissa * 10 + (b - ZERO);
        exponent--;
        digits++;
        p++;
      }
    }
    if (digits > 0 && p < len && (bytes[p] | 0x20) === 0x65 /* e or E */) {
      p++;
      let expNegative = false;
      if (p < len && (bytes[p] === MINUS || bytes[p] === PLUS)) expNegative = bytes[p++] === MINUS;
      let e = 0;
      const expStart = p;
      while (p < len && (b = bytes[p]) >= ZERO && b <= NINE && e < 100000) {
        e = e * 10 + (b - ZERO);
        p++;
      }
      if (p === expStart) return this.readNumberSlow(start);
      exponent += expNegative ? -e : e;
    }
    if (digits === 0 || (p < len && !isTokenEnd(bytes[p], this.hashComments))) return this.readNumberSlow(start);
    if (mantissa >= MAX_EXACT || exponent > 22 || exponent < -22) return this.readNumberSlow(start);
    this.pos = p;
    const value = exponent >= 0 ? mantissa * POW10[exponent] : mantissa / POW10[-exponent];
    return negative ? -value : value;
  }

  /** Exact (but slower) parse for long mantissas, big exponents, nan/inf spellings and errors. */
  private readNumberSlow(start: number): number {
    this.pos = start;
    const end = this.tokenEnd();
    if (end === start) {
      this.fail(this.pos >= this.bytes.length ? 'expected a number, found the end of the file' : 'expected a number, found the end of the line');
    }
    const text = latin1(this.bytes, start, end);
    // Number() alone would also take hex, binary and octal literals.
    const value = DECIMAL.test(text) ? Number(text) : nonFiniteWord(text);
    if (Number.isNaN(value) && !/^[+-]?nan/i.test(text)) this.fail(`bad number '${clip(text)}'`);
    this.pos = end;
    return value;
  }

  /** Reads an integer (after blanks on the current line); anything else is an error naming the line. */
  readInt(what: string): number {
    this.skipBlanks();
    const start = this.pos;
    const value = this.readDigits();
    const { bytes, pos } = this;
    if (Number.isNaN(value) || (pos < bytes.length && !isTokenEnd(bytes[pos], this.hashComments)) || Math.abs(value) > Number.MAX_SAFE_INTEGER) {
      this.pos = start;
      const token = this.peekToken();
      this.fail(token === '' ? `expected ${what}, found the end of the ${pos >= bytes.length ? 'file' : 'line'}` : `bad ${what} '${clip(token)}'`);
    }
    return value;
  }

  /**
   * Reads an optional sign and decimal digits at `pos` and moves past them, or returns NaN (and stays)
   * when there are no digits: what may follow is the caller's to check.
   */
  readDigits(): number {
    const { bytes } = this;
    const len = bytes.length;
    let p = this.pos;
    let negative = false;
    if (p < len && (bytes[p] === MINUS || bytes[p] === PLUS)) negative = bytes[p++] === MINUS;
    const digitsStart = p;
    let value = 0;
    let b = 0;
    while (p < len && (b = bytes[p]) >= ZERO && b <= NINE) {
      value = value * 10 + (b - ZERO);
      p++;
    }
    if (p === digitsStart) return NaN;
    this.pos = p;
    return negative ? -value : value;
  }

  /** Throws a MeshFormatError naming the format and the current line. */
  fail(message: string): never {
    throw new MeshFormatError(`${this.label}: line ${this.line}: ${message}`);
  }
}

/** Decodes ASCII/latin-1 bytes (tokens, headers) to a string. */
export function latin1(bytes: Uint8Array, start: number, end: number): string {
  let s = '';
  // apply() takes the typed array as it is (spreading would iterate it); chunks bound the arguments.
  for (let i = start; i < end; i += 4096) {
    s += String.fromCharCode.apply(null, bytes.subarray(i, Math.min(end, i + 4096)) as unknown as number[]);
  }
  return s;
}

/** ASCII bytes of a keyword, for TextScanner.tokenIs. */
export function ascii(word: string): Uint8Array {
  return Uint8Array.from(word, (c) => c.charCodeAt(0));
}

/** Shortens a token quoted in an error message so that the message stays one readable line. */
export function clip(text: string): string {
  const printable = text.replace(/[^\x20-\x7e]/g, '?');
  return printable.length > 24 ? `${printable.slice(0, 24)}...` : printable;
}

/** Spellings of infinity (C's "inf", "-infinity", JavaScript's "Infinity"); NaN for anything else. */
function nonFiniteWord(text: string): number {
  const m = /^([+-]?)inf(inity)?$/i.exec(text);
  if (m) return m[1] === '-' ? -Infinity : Infinity;
  return NaN;
}
