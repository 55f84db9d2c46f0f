using System;
using System.Runtime.InteropServices;

namespace GregoryTerrain
{
    /// <summary>
    /// One patch of <c>_ControlPoints</c> as the GPU reads it: the mirror of the HLSL
    /// <c>struct GregoryPatchRecord { float4 points[20]; }</c> (generated: Shaders/Terrain/GregoryPatchRecord.cs.hlsl),
    /// 320 bytes, blittable, <c>point</c>k at byte 16 k (the array's stride): slot k of
    /// <see cref="GregoryPatch"/> as <see cref="GpuLayout"/> packs it. ShaderContractTests compares
    /// this layout with the one the shader compiler gives.
    /// <para>Twenty named fields, not a fixed array: a fixed buffer needs unsafe code, and a managed
    /// array would not be blittable. The indexer is the HLSL's <c>points[k]</c>.</para>
    /// </summary>
    [StructLayout(LayoutKind.Sequential)]
    [GenerateHlsl("Shaders/Terrain/GregoryPatchRecord.cs.hlsl", Record = true)]
    internal struct GregoryPatchRecord
    {
        /// <summary>Points per record: <see cref="GregoryPatch.SlotCount"/>, the HLSL array's length.</summary>
        public const int PointCount = 20;
        /// <summary>Bytes per record: the StructuredBuffer's stride.</summary>
        public const int Stride = PointCount * 16;

        // Instance fields only below, in slot order: the layout is the declaration order.
        [HlslArray("points", PointCount)]
        [HlslComment("the 20 control points in the slot order of GregoryPatch.hlsl: xyz = P - R_p, w of points 0..2 = R_p, of the others 0")]
        public Float4 point0;
        public Float4 point1;
        public Float4 point2;
        public Float4 point3;
        public Float4 point4;
        public Float4 point5;
        public Float4 point6;
        public Float4 point7;
        public Float4 point8;
        public Float4 point9;
        public Float4 point10;
        public Float4 point11;
        public Float4 point12;
        public Float4 point13;
        public Float4 point14;
        public Float4 point15;
        public Float4 point16;
        public Float4 point17;
        public Float4 point18;
        public Float4 point19;

        /// <summary>Point <paramref name="k"/> (slot k), as HLSL <c>record.points[k]</c>.</summary>
        public Float4 this[int k]
        {
            readonly get => k switch
            {
                0 => point0, 1 => point1, 2 => point2, 3 => point3, 4 => point4,
                5 => point5, 6 => point6, 7 => point7, 8 => point8, 9 => point9,
                10 => point10, 11 => point11, 12 => point12, 13 => point13, 14 => point14,
                15 => point15, 16 => point16, 17 => point17, 18 => point18, 19 => point19,
                _ => throw new ArgumentOutOfRangeException(nameof(k), k, "a patch record holds points 0..19"),
            };
            set
            {
                switch (k)
                {
                    case 0: point0 = value; break;
                    case 1: point1 = value; break;
                    case 2: point2 = value; break;
                    case 3: point3 = value; break;
                    case 4: point4 = value; break;
                    case 5: point5 = value; break;
                    case 6: point6 = value; break;
                    case 7: point7 = value; break;
                    case 8: point8 = value; break;
                    case 9: point9 = value; break;
                    case 10: point10 = value; break;
                    case 11: point11 = value; break;
                    case 12: point12 = value; break;
                    case 13: point13 = value; break;
                    case 14: point14 = value; break;
                    case 15: point15 = value; break;
                    case 16: point16 = value; break;
                    case 17: point17 = value; break;
                    case 18: point18 = value; break;
                    case 19: point19 = value; break;
                    default: throw new ArgumentOutOfRangeException(nameof(k), k, "a patch record holds points 0..19");
                }
            }
        }
    }
}
