using System;
using System.Collections.Generic;
using System.Text;

namespace GregoryTerrain
{
    internal enum JsonKind { Object, Array, String, Number, True, False, Null }

    /// <summary>A parsed JSON value with where it started (1-based line and column), for error messages.</summary>
    internal sealed class JsonValue
    {
        public JsonKind Kind;
        public string Text;                 // string contents, or a number's literal text
        public List<JsonValue> Items;       // array items
        public List<KeyValuePair<string, JsonValue>> Members; // object members, in order
        public int Line, Column;

        public JsonValue Get(string name)
        {
            if (Members == null) return null;
            foreach (var kv in Members) if (kv.Key == name) return kv.Value;
            return null;
        }
    }

    /// <summary>
    /// A small strict JSON (RFC 8259) reader for Core's file formats: no comments, no trailing
    /// commas, no NaN/Infinity literals, nesting limited to 64. Throws FormatException with the line
    /// and column of the problem.
    /// </summary>
    internal sealed class JsonReader
    {
        const int MaxDepth = 64;
        readonly string s;
        int pos, line = 1, lineStart;

        public JsonReader(string text) { s = text; }

        public JsonValue ReadDocument()
        {
            SkipSpace();
            JsonValue v = ReadValue(0);
            SkipSpace();
            if (pos < s.Length) throw Error($"unexpected '{s[pos]}' after the end of the document");
            return v;
        }

        JsonValue ReadValue(int depth)
        {
            if (depth > MaxDepth) throw Error("nesting deeper than " + MaxDepth);
            if (pos >= s.Length) throw Error("unexpected end of input (the file is truncated)");
            var v = new JsonValue { Line = line, Column = pos - lineStart + 1 };
            char c = s[pos];
            if (c == '{') ReadObject(v, depth);
            else if (c == '[') ReadArray(v, depth);
            else if (c == '"') { v.Kind = JsonKind.String; v.Text = ReadString(); }
            else if (c == '-' || (c >= '0' && c <= '9')) { v.Kind = JsonKind.Number; v.Text = ReadNumber(); }
            else if (Literal("true")) v.Kind = JsonKind.True;
            else if (Literal("false")) v.Kind = JsonKind.False;
            else if (Literal("null")) v.Kind = JsonKind.Null;
            else throw Error($"unexpected '{Snippet()}', expected a value (JSON has no NaN or Infinity)");
            return v;
        }

        void ReadObject(JsonValue v, int depth)
        {
            v.Kind = JsonKind.Object;
            v.Members = new List<KeyValuePair<string, JsonValue>>();
            pos++;
            SkipSpace();
            if (Peek() == '}') { pos++; return; }
            while (true)
            {
                SkipSpace();
                if (Peek() != '"') throw Error("expected a member name in quotes");
                string name = ReadString();
                SkipSpace();
                Expect(':');
                SkipSpace();
                v.Members.Add(new KeyValuePair<string, JsonValue>(name, ReadValue(depth + 1)));
                SkipSpace();
                if (Peek() == ',') { pos++; continue; }
                Expect('}');
                return;
            }
        }

        void ReadArray(JsonValue v, int depth)
        {
            v.Kind = JsonKind.Array;
            v.Items = new List<JsonValue>();
            pos++;
            SkipSpace();
            if (Peek() == ']') { pos++; return; }
            while (true)
            {
                SkipSpace();
                v.Items.Add(ReadValue(depth + 1));
                SkipSpace();
                if (Peek() == ',') { pos++; continue; }
                Expect(']');
                return;
            }
        }

        string ReadString()
        {
            pos++; // opening quote
            var sb = new StringBuilder();
            while (true)
            {
                if (pos >= s.Length) throw Error("unexpected end of input inside a string (the file is truncated)");
                char c = s[pos++];
                if (c == '"') return sb.ToString();
                if (c < ' ') throw Error("control character inside a string");
                if (c != '\\') { sb.Append(c); continue; }
                if (pos >= s.Length) throw Error("unexpected end of input inside a string (the file is truncated)");
                char e = s[pos++];
                switch (e)
                {
                    case '"': sb.Append('"'); break;
                    case '\\': sb.Append('\\'); break;
                    case '/': sb.Append('/'); break;
                    case 'b': sb.Append('\b'); break;
                    case 'f': sb.Append('\f'); break;
                    case 'n': sb.Append('\n'); break;
                    case 'r': sb.Append('\r'); break;
                    case 't': sb.Append('\t'); break;
                    case 'u':
                        if (pos + 4 > s.Length) throw Error("truncated \\u escape");
                        int code = 0;
                        for (int k = 0; k < 4; k++)
                        {
                            int h = Hex(s[pos++]);
                            if (h < 0) throw Error("bad hex digit in \\u escape");
                            code = code * 16 + h;
                        }
                        sb.Append((char)code);
                        break;
                    default: throw Error($"bad escape '\\{e}'");
                }
            }
        }

        static int Hex(char c) => c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;

        /// <summary>The literal text of a number, checked against JSON's grammar.</summary>
        string ReadNumber()
        {
            int start = pos;
            if (Peek() == '-') pos++;
            if (Peek() == '0') pos++;
            else if (IsDigit(Peek())) while (IsDigit(Peek())) pos++;
            else throw Error("bad number: expected a digit");
            if (Peek() == '.')
            {
                pos++;
                if (!IsDigit(Peek())) throw Error("bad number: expected a digit after '.'");
                while (IsDigit(Peek())) pos++;
            }
            if (Peek() == 'e' || Peek() == 'E')
            {
                pos++;
                if (Peek() == '+' || Peek() == '-') pos++;
                if (!IsDigit(Peek())) throw Error("bad number: expected a digit in the exponent");
                while (IsDigit(Peek())) pos++;
            }
            return s.Substring(start, pos - start);
        }

        static bool IsDigit(char c) => c >= '0' && c <= '9';

        bool Literal(string word)
        {
            if (string.CompareOrdinal(s, pos, word, 0, word.Length) != 0) return false;
            pos += word.Length;
            return true;
        }

        char Peek() => pos < s.Length ? s[pos] : '\0';

        void Expect(char c)
        {
            if (pos >= s.Length) throw Error($"unexpected end of input, expected '{c}' (the file is truncated)");
            if (s[pos] != c) throw Error($"unexpected '{s[pos]}', expected '{c}'");
            pos++;
        }

        void SkipSpace()
        {
            while (pos < s.Length)
            {
                char c = s[pos];
                if (c == '\n') { line++; lineStart = pos + 1; }
                else if (c != ' ' && c != '\t' && c != '\r') return;
                pos++;
            }
        }

        string Snippet() => s.Substring(pos, Math.Min(12, s.Length - pos));

        FormatException Error(string what) =>
            new FormatException($"JSON: {what} (line {line}, column {pos - lineStart + 1}).");
    }
}
