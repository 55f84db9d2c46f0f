using System;
using System.Runtime.InteropServices;

namespace GregoryTerrain
{
    /// <summary>
    /// A contract struct (<see cref="GenerateHlslAttribute"/>: sequential Float4 fields) read through
    /// its own bytes, so the order can never disagree with the layout the shaders get.
    /// </summary>
    internal interface IFloat4Block
    {
        /// <summary>Float4 <paramref name="index"/>, in field order.</summary>
        Float4 this[int index] { get; }
    }

    internal static class Float4Block
    {
        /// <summary>Float4 <paramref name="index"/> of <paramref name="block"/>, which holds <paramref name="count"/>.</summary>
        public static Float4 At<T>(ref T block, int index, int count) where T : unmanaged =>
            (uint)index < (uint)count
                ? MemoryMarshal.Cast<T, Float4>(MemoryMarshal.CreateSpan(ref block, 1))[index]
                : throw new ArgumentOutOfRangeException(nameof(index), index, $"{typeof(T).Name} has {count} float4");

        /// <summary>The block's floats, in field order.</summary>
        public static float[] Pack<T>(T block) where T : unmanaged =>
            MemoryMarshal.Cast<T, float>(MemoryMarshal.CreateReadOnlySpan(ref block, 1)).ToArray();
    }
}
