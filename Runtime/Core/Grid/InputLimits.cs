using System;
using System.Globalization;
using System.IO;

namespace GregoryTerrain
{
    /// <summary>
    /// The limits that protect float32, the GPU and the machine from hostile input, one rule per
    /// fact, and the helpers every entry point uses to refuse a value by name (troubleshooting.md
    /// lists the messages). Patch counts live in <see cref="GpuLayout.CheckSize"/>, range sizes in
    /// <see cref="TerrainRange.Validate"/>; this file holds the rest.
    /// </summary>
    internal static class InputLimits
    {
        /// <summary>The largest magnitude a float32 holds (what the GPU buffers carry).</summary>
        public const double MaxFloat = float.MaxValue;

        /// <summary>The largest grid JSON file read (1 GiB: a grid at the GPU's patch limit, written in full precision, is about 8 GB, so this is the tighter limit).</summary>
        public const long MaxJsonBytes = 1L << 30;

        /// <summary>The most samples per shared edge the authoring assembly's <c>ContinuityMeasure</c> takes (steps of 1/4096).</summary>
        public const int MaxSamplesPerEdge = 4097;

        /// <summary>Characters of a user's value that an error message quotes before cutting it short.</summary>
        public const int QuotedLength = 64;

        /// <summary>
        /// <paramref name="text"/> as a message quotes it: whole when short, else its first
        /// <see cref="QuotedLength"/> characters and the total length (a 200 MB value is never echoed).
        /// </summary>
        public static string Quote(string text) => text == null ? "null" : Quote(text, text.Length);

        /// <summary>As <see cref="Quote(string)"/>, for a value of which only the start (<paramref name="kept"/>) was kept, <paramref name="length"/> characters in all.</summary>
        public static string Quote(string kept, long length)
        {
            if (length <= QuotedLength && kept.Length == length) return kept;
            return kept.Substring(0, Math.Min(kept.Length, QuotedLength)) + string.Format(CultureInfo.InvariantCulture, "... ({0} characters)", length);
        }

        /// <summary>Throws ArgumentException naming <paramref name="field"/> unless the value is finite and within float32's range.</summary>
        public static void CheckFloat(double value, string field)
        {
            if (double.IsNaN(value) || double.IsInfinity(value))
                throw new ArgumentException(F("{0} = {1:R} is not finite.", field, value), field);
            if (Math.Abs(value) > MaxFloat)
                throw new ArgumentException(F("{0} = {1:R} is outside float32's range (|value| <= {2:R}); the GPU cannot hold it.", field, value, MaxFloat), field);
        }

        /// <summary>True when a double survives the trip to float32 (finite, |value| within float's range).</summary>
        public static bool FitsFloat(double value) => Math.Abs(value) <= MaxFloat;

        /// <summary>Throws ArgumentException unless 2 &lt;= samples &lt;= <see cref="MaxSamplesPerEdge"/>.</summary>
        public static void CheckSamplesPerEdge(int samples, string field = "samplesPerEdge")
        {
            if (samples < 2 || samples > MaxSamplesPerEdge)
                throw new ArgumentException(F("{0} = {1} must lie in [2, {2}] (both ends of an edge; steps of 1/{3} at most).",
                    field, samples, MaxSamplesPerEdge, MaxSamplesPerEdge - 1), field);
        }

        /// <summary>
        /// Throws IOException unless <paramref name="path"/> is an existing file of at most
        /// <paramref name="maxBytes"/> bytes: a folder, a missing file or an oversized one is named
        /// before anything is read.
        /// </summary>
        public static void CheckFileToRead(string path, long maxBytes)
        {
            if (string.IsNullOrEmpty(path)) throw new ArgumentException("the file path is empty.", nameof(path));
            if (Directory.Exists(path)) throw new IOException($"{Quote(path)} is a folder, expected a file.");
            var info = new FileInfo(path);
            if (!info.Exists) throw new FileNotFoundException($"{Quote(path)} does not exist.", path);
            if (info.Length > maxBytes)
                throw new IOException(F("{0} is {1} bytes, more than the limit of {2} bytes.", Quote(path), info.Length, maxBytes));
        }

        static string F(string format, params object[] args) => string.Format(CultureInfo.InvariantCulture, format, args);
    }
}
