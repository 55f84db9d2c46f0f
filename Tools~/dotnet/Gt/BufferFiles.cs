using System;
using System.IO;
using System.Runtime.InteropServices;

namespace GregoryTerrain.Rig
{
    /// <summary>Raw little-endian float32 files: how the rig hands Core's packed buffers to the harness.</summary>
    static class BufferFiles
    {
        public static void Write(string path, float[] values)
        {
            if (!BitConverter.IsLittleEndian) throw new PlatformNotSupportedException("the harness expects little-endian floats");
            File.WriteAllBytes(path, MemoryMarshal.AsBytes(values.AsSpan()).ToArray());
        }

        public static float[] Read(string path)
        {
            byte[] bytes = File.ReadAllBytes(path);
            if (bytes.Length % 4 != 0)
                throw new FormatException($"{path}: {bytes.Length} bytes is not a whole number of float32 values");
            return MemoryMarshal.Cast<byte, float>(bytes).ToArray();
        }
    }
}
