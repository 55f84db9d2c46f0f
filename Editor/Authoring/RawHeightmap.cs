using System;
using System.Buffers.Binary;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>How a RAW heightmap file stores one sample.</summary>
    internal enum RawSampleFormat
    {
        /// <summary>Unsigned 16-bit, least significant byte first (Unity's "Windows" RAW).</summary>
        UInt16LittleEndian,
        /// <summary>Unsigned 16-bit, most significant byte first (Unity's "Mac" RAW).</summary>
        UInt16BigEndian,
        /// <summary>Signed 16-bit, most significant byte first (SRTM .hgt: metres, -32768 = void).</summary>
        Int16BigEndian,
        /// <summary>Signed 16-bit, least significant byte first.</summary>
        Int16LittleEndian,
        /// <summary>IEEE 32-bit float, little-endian.</summary>
        Float32LittleEndian,
        /// <summary>IEEE 32-bit float, big-endian.</summary>
        Float32BigEndian,
    }

    /// <summary>
    /// Which edge of the terrain a RAW file's first row lies on. The terrain's y = 0 edge is its south
    /// edge (Unity's -Z side); the fitter puts sample row r at y = r / (H - 1).
    /// </summary>
    internal enum RawRowOrder
    {
        /// <summary>North first for SRTM <c>.hgt</c> files (stored north to south), south first for any
        /// other file, as Unity's own Import Raw reads a RAW with Flip Vertically off.</summary>
        ByFileType,
        /// <summary>Row 0 is the south edge (Unity's RAW export and import, Flip Vertically off).</summary>
        SouthFirst,
        /// <summary>Row 0 is the north edge (SRTM, most GIS exports; Unity's Flip Vertically on).</summary>
        NorthFirst,
    }

    /// <summary>
    /// Reads headerless RAW heightmaps: W x H samples, rows one after another, no padding. The size
    /// is inferred when the file is square and checked against the byte count otherwise; every
    /// error names the file and what is wrong. Values come out as stored (no scaling); a sample equal
    /// to the void value (SRTM's -32768) or a non-finite float becomes NaN, for
    /// <see cref="HeightmapVoids.Fill"/>.
    /// </summary>
    internal static class RawHeightmap
    {
        /// <summary>SRTM's "no data" value.</summary>
        public const int SrtmVoid = -32768;

        public static int BytesPerSample(RawSampleFormat format) =>
            format == RawSampleFormat.Float32LittleEndian || format == RawSampleFormat.Float32BigEndian ? 4 : 2;

        /// <summary>
        /// The sample size of a file of <paramref name="byteCount"/> bytes. With width and height both
        /// 0 the file must be square (side = sqrt(samples)); with one given the other follows; with
        /// both given they must match the byte count.
        /// </summary>
        public static void InferSize(string fileName, long byteCount, RawSampleFormat format, ref int width, ref int height)
        {
            int bps = BytesPerSample(format);
            if (width < 0 || height < 0)
                throw new ArgumentException($"{fileName}: width = {width}, height = {height}; give positive sizes or 0 to infer them.");
            if (byteCount < 4L * bps)
                throw new ArgumentException($"{fileName}: {byteCount} bytes is less than 2 x 2 samples of {bps} bytes.");
            if (byteCount % bps != 0)
                throw new ArgumentException($"{fileName}: {byteCount} bytes is not a whole number of {bps}-byte samples: wrong format ({format})?");
            long samples = byteCount / bps;
            if (width == 0 && height == 0)
            {
                long side = (long)Math.Round(Math.Sqrt(samples));
                if (side * side != samples)
                    throw new ArgumentException($"{fileName}: {samples} samples of {bps} bytes is not a square; give its width or height.");
                width = height = checked((int)side);
            }
            else if (width == 0 || height == 0)
            {
                long known = width == 0 ? height : width;
                if (samples % known != 0)
                    throw new ArgumentException($"{fileName}: {samples} samples do not divide into rows of {known}; check the size and format ({format}).");
                if (width == 0) width = checked((int)(samples / known)); else height = checked((int)(samples / known));
            }
            else if ((long)width * height != samples)
                throw new ArgumentException($"{fileName}: {byteCount} bytes hold {samples} samples of {bps} bytes; {width} x {height} needs {(long)width * height}. Check the size and format ({format}).");
            if (width < 2 || height < 2)
                throw new ArgumentException($"{fileName}: {width} x {height} samples, need at least 2 x 2.");
        }

        /// <summary>
        /// A whole RAW file's heights, south row first (what the fitter puts at the terrain's y = 0
        /// edge): the size inferred or checked (<see cref="InferSize"/>), samples decoded
        /// (<see cref="Decode"/>), rows flipped when the file's first row is the north edge
        /// (<see cref="FirstRowIsNorth"/>).
        /// </summary>
        public static double[] ReadSouthFirst(string fileName, ReadOnlySpan<byte> bytes, RawSampleFormat format, RawRowOrder order,
            ref int width, ref int height, int? voidValue = null)
        {
            bool flip = FirstRowIsNorth(fileName, order);
            InferSize(fileName, bytes.Length, format, ref width, ref height);
            double[] heights = Decode(fileName, bytes, width, height, format, voidValue);
            if (flip) FlipRows(heights, width, height);
            return heights;
        }

        /// <summary>Whether a file's first row is the terrain's north edge; <see cref="RawRowOrder.ByFileType"/> decides by the extension.</summary>
        public static bool FirstRowIsNorth(string fileName, RawRowOrder order)
        {
            switch (order)
            {
                case RawRowOrder.NorthFirst: return true;
                case RawRowOrder.SouthFirst: return false;
                case RawRowOrder.ByFileType:
                    return string.Equals(System.IO.Path.GetExtension(fileName ?? ""), ".hgt", StringComparison.OrdinalIgnoreCase);
                default:
                    throw new ArgumentException(string.Format(CultureInfo.InvariantCulture, "{0}: order = {1} is not a row order.", fileName, order), nameof(order));
            }
        }

        /// <summary>Reverses the order of the <paramref name="height"/> rows of <paramref name="width"/> samples, in place.</summary>
        public static void FlipRows(double[] samples, int width, int height)
        {
            if (samples == null) throw new ArgumentNullException(nameof(samples));
            if (width < 1 || height < 1 || (long)width * height != samples.Length)
                throw new ArgumentException($"samples.Length = {samples.Length} is not width {width} x height {height}.", nameof(samples));
            for (int top = 0, bottom = height - 1; top < bottom; top++, bottom--)
                for (int c = 0; c < width; c++)
                {
                    int a = top * width + c, b = bottom * width + c;
                    (samples[a], samples[b]) = (samples[b], samples[a]);
                }
        }

        /// <summary>Decodes W x H samples (sizes from <see cref="InferSize"/>) to doubles; voids become NaN.</summary>
        public static double[] Decode(string fileName, ReadOnlySpan<byte> bytes, int width, int height, RawSampleFormat format, int? voidValue = null)
        {
            int bps = BytesPerSample(format);
            if ((long)width * height * bps != bytes.Length)
                throw new ArgumentException($"{fileName}: {bytes.Length} bytes, {width} x {height} samples of {bps} bytes need {(long)width * height * bps}.");
            var h = new double[width * height];
            for (int k = 0; k < h.Length; k++)
            {
                ReadOnlySpan<byte> b = bytes.Slice(k * bps, bps);
                double v;
                switch (format)
                {
                    case RawSampleFormat.UInt16LittleEndian: v = BinaryPrimitives.ReadUInt16LittleEndian(b); break;
                    case RawSampleFormat.UInt16BigEndian: v = BinaryPrimitives.ReadUInt16BigEndian(b); break;
                    case RawSampleFormat.Int16BigEndian: v = BinaryPrimitives.ReadInt16BigEndian(b); break;
                    case RawSampleFormat.Int16LittleEndian: v = BinaryPrimitives.ReadInt16LittleEndian(b); break;
                    case RawSampleFormat.Float32LittleEndian: v = BitConverter.Int32BitsToSingle(BinaryPrimitives.ReadInt32LittleEndian(b)); break;
                    case RawSampleFormat.Float32BigEndian: v = BitConverter.Int32BitsToSingle(BinaryPrimitives.ReadInt32BigEndian(b)); break;
                    default: throw new ArgumentException(string.Format(CultureInfo.InvariantCulture, "{0}: format = {1} is not a RAW sample format.", fileName, format), nameof(format));
                }
                if (voidValue.HasValue && v == voidValue.Value) v = double.NaN;
                else if (!GMath.isfinite(v)) v = double.NaN;
                h[k] = v;
            }
            return h;
        }
    }
}
