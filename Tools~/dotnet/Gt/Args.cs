using System;
using System.Collections.Generic;
using System.Globalization;

namespace GregoryTerrain.Rig
{
    /// <summary>Minimal "--name value" / "--flag" parser with errors that name the option and value.</summary>
    sealed class Args
    {
        readonly Dictionary<string, string> _values = new Dictionary<string, string>(StringComparer.Ordinal);
        readonly HashSet<string> _used = new HashSet<string>(StringComparer.Ordinal);

        public Args(string[] argv, int start)
        {
            for (int i = start; i < argv.Length; i++)
            {
                string a = argv[i];
                if (!a.StartsWith("--", StringComparison.Ordinal))
                    throw new ArgumentException($"unexpected argument '{a}' (options are --name value)");
                bool hasValue = i + 1 < argv.Length && !argv[i + 1].StartsWith("--", StringComparison.Ordinal);
                _values[a.Substring(2)] = hasValue ? argv[++i] : "";
            }
        }

        public bool Flag(string name) { _used.Add(name); return _values.ContainsKey(name); }

        public string String(string name, string fallback = null)
        {
            _used.Add(name);
            if (_values.TryGetValue(name, out var v)) return v;
            if (fallback != null) return fallback;
            throw new ArgumentException($"--{name} is required");
        }

        public double Double(string name, double? fallback = null)
        {
            string s = String(name, fallback?.ToString("R", CultureInfo.InvariantCulture));
            if (!double.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out double v))
                throw new ArgumentException($"--{name} '{s}' is not a number");
            return v;
        }

        public int Int(string name, int? fallback = null)
        {
            string s = String(name, fallback?.ToString(CultureInfo.InvariantCulture));
            if (!int.TryParse(s, NumberStyles.Integer, CultureInfo.InvariantCulture, out int v))
                throw new ArgumentException($"--{name} '{s}' is not an integer");
            return v;
        }

        public double[] Doubles(string name, int count, string fallback = null)
        {
            string s = String(name, fallback);
            var parts = s.Split(',');
            if (parts.Length != count)
                throw new ArgumentException($"--{name} '{s}' needs {count} comma-separated numbers");
            var r = new double[count];
            for (int i = 0; i < count; i++)
                if (!double.TryParse(parts[i], NumberStyles.Float, CultureInfo.InvariantCulture, out r[i]))
                    throw new ArgumentException($"--{name} '{s}': '{parts[i]}' is not a number");
            return r;
        }
    }
}
