using System;
using System.Globalization;
using System.IO;
using System.Text;

namespace GregoryTerrain
{
    /// <summary>What the next JSON value is, from its first character.</summary>
    internal enum JsonKind { Object, Array, String, Number, True, False, Null, End, Invalid }

    /// <summary>
    /// A small strict JSON (RFC 8259) pull tokenizer for Core's file formats: no comments, no
    /// trailing commas, no NaN/Infinity literals. It streams from a TextReader through a fixed
    /// buffer and builds no tree, so the caller reads numbers straight into its own arrays and
    /// memory stays bounded by what the caller keeps. Nesting is the caller's (it asks for each
    /// bracket), so a deeply nested file is refused at its first unexpected bracket, with no
    /// recursion. Strings and numbers longer than a caller-given limit are refused or quoted short.
    /// Throws FormatException with the 1-based line and column of the problem.
    /// </summary>
    internal sealed class JsonReader
    {
        /// <summary>Longest number literal accepted (a double never needs more than ~770 digits to round-trip; 1000 leaves room).</summary>
        public const int MaxNumberLength = 1000;

        readonly TextReader _reader;
        readonly char[] _buffer = new char[1 << 16];
        readonly StringBuilder _token = new StringBuilder();
        readonly char[] _number = new char[MaxNumberLength];
        int _numberLength;
        int _length, _index;
        long _line = 1, _column = 1;

        public JsonReader(TextReader reader) { _reader = reader ?? throw new ArgumentNullException(nameof(reader)); }

        /// <summary>Line and column of the next character (after <see cref="Peek"/>, of the next token).</summary>
        public long Line => _line;
        public long Column => _column;

        int PeekChar()
        {
            if (_index < _length) return _buffer[_index];
            _length = _reader.Read(_buffer, 0, _buffer.Length);
            _index = 0;
            return _length > 0 ? _buffer[0] : -1;
        }

        char NextChar()
        {
            int c = PeekChar();
            if (c < 0) throw Error("unexpected end of input (the file is truncated)");
            _index++;
            if (c == '\n') { _line++; _column = 1; } else _column++;
            return (char)c;
        }

        void SkipSpace()
        {
            while (true)
            {
                int c = PeekChar();
                if (c != ' ' && c != '\t' && c != '\r' && c != '\n') return;
                NextChar();
            }
        }

        /// <summary>Skips white space and says what the next value is (End at the end of input).</summary>
        public JsonKind Peek()
        {
            SkipSpace();
            int c = PeekChar();
            switch (c)
            {
                case -1: return JsonKind.End;
                case '{': return JsonKind.Object;
                case '[': return JsonKind.Array;
                case '"': return JsonKind.String;
                case 't': return JsonKind.True;
                case 'f': return JsonKind.False;
                case 'n': return JsonKind.Null;
                default: return c == '-' || (c >= '0' && c <= '9') ? JsonKind.Number : JsonKind.Invalid;
            }
        }

        /// <summary>Consumes <paramref name="c"/> (after white space) or throws.</summary>
        public void Expect(char c)
        {
            SkipSpace();
            int n = PeekChar();
            if (n != c) throw Error($"unexpected {Describe(n)}, expected '{c}'");
            NextChar();
        }

        /// <summary>After an item of an array or object: true at ',' (another follows), false at <paramref name="close"/>.</summary>
        public bool Continues(char close)
        {
            SkipSpace();
            int n = PeekChar();
            if (n == ',') { NextChar(); return true; }
            if (n == close) { NextChar(); return false; }
            throw Error($"unexpected {Describe(n)}, expected ',' or '{close}'");
        }

        /// <summary>True (and consumed) when the next character is <paramref name="close"/>: an empty array or object.</summary>
        public bool TryClose(char close)
        {
            SkipSpace();
            if (PeekChar() != close) return false;
            NextChar();
            return true;
        }

        /// <summary>Throws unless only white space is left.</summary>
        public void ExpectEnd()
        {
            SkipSpace();
            int n = PeekChar();
            if (n >= 0) throw Error($"unexpected {Describe(n)} after the end of the document");
        }

        /// <summary>
        /// A string value. At most <paramref name="keep"/> characters are kept (the rest is read and
        /// checked but dropped), and <paramref name="length"/> is the full length, so a huge value is
        /// never held nor echoed whole.
        /// </summary>
        public string ReadString(int keep, out long length)
        {
            SkipSpace();
            if (PeekChar() != '"') throw Error($"unexpected {Describe(PeekChar())}, expected a string");
            NextChar();
            _token.Clear();
            length = 0;
            while (true)
            {
                int c = PeekChar();
                if (c < 0) throw Error("unexpected end of input inside a string (the file is truncated)");
                NextChar();
                if (c == '"') return _token.ToString();
                if (c < ' ') throw Error("control character inside a string");
                char v = (char)c;
                if (c == '\\') v = Escape();
                if (length++ < keep) _token.Append(v);
            }
        }

        char Escape()
        {
            char e = NextChar();
            switch (e)
            {
                case '"': return '"';
                case '\\': return '\\';
                case '/': return '/';
                case 'b': return '\b';
                case 'f': return '\f';
                case 'n': return '\n';
                case 'r': return '\r';
                case 't': return '\t';
                case 'u':
                    int code = 0;
                    for (int k = 0; k < 4; k++)
                    {
                        int h = Hex(NextChar());
                        if (h < 0) throw Error("bad hex digit in \\u escape");
                        code = code * 16 + h;
                    }
                    return (char)code;
                default: throw Error($"bad escape '\\{e}'");
            }
        }

        static int Hex(char c) => c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;

        /// <summary>
        /// A number, checked against JSON's grammar, as a double; <see cref="NumberText"/> is its
        /// literal (at most <see cref="MaxNumberLength"/> characters). A literal beyond double's
        /// range gives an infinity: the caller names it. Parsed from a fixed buffer: no allocation.
        /// </summary>
        public double ReadNumber()
        {
            SkipSpace();
            _numberLength = 0;
            if (PeekChar() == '-') Take();
            if (PeekChar() == '0') Take();
            else if (IsDigit(PeekChar())) TakeDigits();
            else throw Error($"unexpected {Describe(PeekChar())}, expected a number (JSON has no NaN or Infinity)");
            if (PeekChar() == '.')
            {
                Take();
                if (!IsDigit(PeekChar())) throw Error($"bad number: unexpected {Describe(PeekChar())} after '.', expected a digit");
                TakeDigits();
            }
            if (PeekChar() == 'e' || PeekChar() == 'E')
            {
                Take();
                if (PeekChar() == '+' || PeekChar() == '-') Take();
                if (!IsDigit(PeekChar())) throw Error($"bad number: unexpected {Describe(PeekChar())} in the exponent, expected a digit");
                TakeDigits();
            }
            int next = PeekChar();
            if (!(next < 0 || next == ',' || next == ']' || next == '}' || next == ' ' || next == '\t' || next == '\r' || next == '\n'))
                throw Error($"bad number: unexpected {Describe(next)} after {NumberText}");
            // The grammar is checked; only a magnitude beyond double's range fails to parse (on
            // runtimes that throw rather than return an infinity).
            if (!double.TryParse(new ReadOnlySpan<char>(_number, 0, _numberLength), NumberStyles.Float, CultureInfo.InvariantCulture, out double d))
                d = _number[0] == '-' ? double.NegativeInfinity : double.PositiveInfinity;
            return d;
        }

        /// <summary>The literal of the last number read (for messages).</summary>
        public string NumberText => new string(_number, 0, _numberLength);

        void TakeDigits() { while (IsDigit(PeekChar())) Take(); }

        void Take()
        {
            if (_numberLength >= MaxNumberLength) throw Error($"a number longer than {MaxNumberLength} characters");
            _number[_numberLength++] = NextChar();
        }

        static bool IsDigit(int c) => c >= '0' && c <= '9';

        /// <summary>Consumes a literal true, false or null.</summary>
        public void ReadLiteral(string word)
        {
            SkipSpace();
            foreach (char w in word)
                if (PeekChar() != w) throw Error($"unexpected {Describe(PeekChar())}, expected '{word}'");
                else NextChar();
        }

        static string Describe(int c) => c < 0 ? "end of input (the file is truncated)" : c < ' ' ? string.Format(CultureInfo.InvariantCulture, "character U+{0:X4}", c) : $"'{(char)c}'";

        public FormatException Error(string what) =>
            new FormatException(string.Format(CultureInfo.InvariantCulture, "JSON: {0} (line {1}, column {2}).", what, _line, _column));
    }
}
