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
        /// Non-Power of 2 scaling: resampled heights), block-compressed (lossy), or half-float (11 significant
        /// bits) from a file of 32-bit channels (<see cref="ExrHas32BitChannels"/>). The fit reads the
        /// file's heights exactly or not at all, as Unity's own heightmap import reads raw data.
        /// </summary>
        public static string ImportProblem(string name, int sourceWidth, int sourceHeight, int width, int height, string format, bool compressed, bool readable,
                                           bool fileHas32BitChannels = false)
        {
            var problems = new System.Collections.Generic.List<string>();
            if (!readable) problems.Add("Read/Write is off, so its texels cannot be read");
            if (fileHas32BitChannels && (format == nameof(HeightTexelFormat.RHalf) || format == nameof(HeightTexelFormat.RGBAHalf)))
                problems.Add($"it is imported at half precision ({format}: 11 significant bits) but its file holds 32-bit floats: the fit would see rounded heights");
            if (width != sourceWidth || height != sourceHeight)
                problems.Add($"it is imported at {width} x {height} but its file is {sourceWidth} x {sourceHeight} (Max Size or Non-Power of 2 resized it): the fit would see resampled heights");
            if (compressed) problems.Add($"it is imported compressed ({format}), which changes the heights: set Compression to None (and in the current platform's override, if any)");
            return problems.Count == 0 ? null : $"'{name}': " + string.Join("; ", problems) + ".";
        }

        /// <summary>
        /// Whether an OpenEXR file's header (its first bytes; 64 KB hold any real header) lists a channel
        /// of 32 bits (FLOAT or UINT), which Unity's default half-float import rounds; null when
        /// <paramref name="header"/> is not an EXR header or ends before its channel list does.
        /// OpenEXR file layout: magic 20000630, a 4-byte version, then attributes (name, type, int32
        /// size, value) up to an empty name; "channels" is a chlist of (name, int32 pixel type, 12
        /// bytes) entries up to an empty name, pixel types 0 UINT, 1 HALF, 2 FLOAT.
        /// </summary>
        public static bool? ExrHas32BitChannels(byte[] header)
        {
            if (header == null || header.Length < 8 || BinaryPrimitives.ReadInt32LittleEndian(header) != 20000630) return null;
            int at = 8;
            while (true)
            {
                string attribute = ReadName(header, ref at), type = attribute == null ? null : ReadName(header, ref at);
                if (attribute == null || attribute.Length == 0 || type == null || at + 4 > header.Length) return null;
                int size = BinaryPrimitives.ReadInt32LittleEndian(header.AsSpan(at));
                at += 4;
                if (size < 0 || at + size > header.Length) return null;
                if (attribute == "channels" && type == "chlist") return ChannelListHas32Bits(header, at, at + size);
                at += size;
            }
        }

        static bool? ChannelListHas32Bits(byte[] bytes, int at, int end)
        {
            bool wide = false;
            while (true)
            {
                string channel = ReadName(bytes, ref at);
                if (channel == null || at > end) return null;
                if (channel.Length == 0) return wide;
                if (at + 16 > end) return null;
                int pixelType = BinaryPrimitives.ReadInt32LittleEndian(bytes.AsSpan(at));
                wide |= pixelType == 0 || pixelType == 2;
                at += 16;
            }
        }

        /// <summary>A NUL-terminated ASCII name at <paramref name="at"/> (moved past it), or null when it runs off the end.</summary>
        static string ReadName(byte[] bytes, ref int at)
        {
            if (at >= bytes.Length) return null;
            int end = Array.IndexOf(bytes, (byte)0, at);
            if (end < 0) return null;
            string name = System.Text.Encoding.ASCII.GetString(bytes, at, end - at);
            at = end + 1;
            return name;
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
