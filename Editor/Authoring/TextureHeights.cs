using System;
using System.Buffers.Binary;

namespace GregoryTerrain
{
    /// <summary>The texel layouts <see cref="TextureHeights"/> reads at full precision (Unity's TextureFormat names).</summary>
    internal enum HeightTexelFormat
    {
        /// <summary>One unsigned 16-bit channel (a 16-bit greyscale PNG imported as R16): value / 65535.</summary>
        R16,
        /// <summary>Four unsigned 16-bit channels (a 16-bit PNG imported as RGBA64): red / 65535.</summary>
        RGBA64,
        /// <summary>One half-float channel (an EXR imported as RHalf).</summary>
        RHalf,
        /// <summary>Four half-float channels (RGBAHalf): red.</summary>
        RGBAHalf,
        /// <summary>One 32-bit float channel (an EXR imported as RFloat).</summary>
        RFloat,
        /// <summary>Four 32-bit float channels (RGBAFloat): red.</summary>
        RGBAFloat,
    }

    /// <summary>
    /// Heights from a texture's raw texel bytes (Unity's <c>Texture2D.GetRawTextureData</c>: mip 0
    /// first, little-endian, rows bottom-up), without passing through 8-bit colour. Integer formats
    /// come out in [0, 1]; float formats as stored. Non-finite texels become NaN (voids).
    /// </summary>
    internal static class TextureHeights
    {
        /// <summary>
        /// Why a texture as imported does not hold its file's heights, or null: not readable, resized
        /// from the file's <paramref name="sourceWidth"/> x <paramref name="sourceHeight"/> (Max Size, or
        /// Non-Power of 2 scaling: resampled heights), or block-compressed (lossy). The fit reads the
        /// file's heights exactly or not at all, as Unity's own heightmap import reads raw data.
        /// </summary>
        public static string ImportProblem(string name, int sourceWidth, int sourceHeight, int width, int height, string format, bool compressed, bool readable)
        {
            var problems = new System.Collections.Generic.List<string>();
            if (!readable) problems.Add("Read/Write is off, so its texels cannot be read");
            if (width != sourceWidth || height != sourceHeight)
                problems.Add($"it is imported at {width} x {height} but its file is {sourceWidth} x {sourceHeight} (Max Size or Non-Power of 2 resized it): the fit would see resampled heights");
            if (compressed) problems.Add($"it is imported compressed ({format}), which changes the heights: set Compression to None (and in the current platform's override, if any)");
            return problems.Count == 0 ? null : $"'{name}': " + string.Join("; ", problems) + ".";
        }

        public static int BytesPerTexel(HeightTexelFormat format)
        {
            switch (format)
            {
                case HeightTexelFormat.R16: case HeightTexelFormat.RHalf: return 2;
                case HeightTexelFormat.RFloat: return 4;
                case HeightTexelFormat.RGBA64: case HeightTexelFormat.RGBAHalf: return 8;
                case HeightTexelFormat.RGBAFloat: return 16;
                default: throw new ArgumentException($"format = {format} is not a height texel format.", nameof(format));
            }
        }

        /// <summary>W x H heights (row r = texture row r) from <paramref name="raw"/>, which holds at least mip 0.</summary>
        public static double[] Decode(string textureName, byte[] raw, int width, int height, HeightTexelFormat format)
        {
            if (raw == null) throw new ArgumentNullException(nameof(raw));
            if (width < 2 || height < 2) throw new ArgumentException($"{textureName}: {width} x {height} texels, need at least 2 x 2.");
            int bpt = BytesPerTexel(format);
            long need = (long)width * height * bpt;
            if (raw.Length < need)
                throw new ArgumentException($"{textureName}: {raw.Length} bytes of texel data, {width} x {height} {format} texels need {need}.");
            var h = new double[width * height];
            for (int k = 0; k < h.Length; k++)
            {
                ReadOnlySpan<byte> t = new ReadOnlySpan<byte>(raw, k * bpt, bpt);
                double v;
                switch (format)
                {
                    case HeightTexelFormat.R16: case HeightTexelFormat.RGBA64: v = BinaryPrimitives.ReadUInt16LittleEndian(t) / 65535.0; break;
                    case HeightTexelFormat.RHalf: case HeightTexelFormat.RGBAHalf: v = HalfToDouble(BinaryPrimitives.ReadUInt16LittleEndian(t)); break;
                    default: v = BitConverter.Int32BitsToSingle(BinaryPrimitives.ReadInt32LittleEndian(t)); break;
                }
                h[k] = GMath.isfinite(v) ? v : double.NaN;
            }
            return h;
        }

        /// <summary>IEEE 754 binary16 to double (subnormals, infinities and NaN included).</summary>
        public static double HalfToDouble(ushort bits)
        {
            int sign = (bits >> 15) != 0 ? -1 : 1, exp = (bits >> 10) & 0x1F, mant = bits & 0x3FF;
            if (exp == 0) return sign * mant * Math.Pow(2, -24);
            if (exp == 31) return mant == 0 ? sign * double.PositiveInfinity : double.NaN;
            return sign * (1 + mant / 1024.0) * Math.Pow(2, exp - 15);
        }
    }
}
