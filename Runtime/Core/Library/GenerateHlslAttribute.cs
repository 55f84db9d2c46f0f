using System;

namespace GregoryTerrain
{
    /// <summary>
    /// Marks a Core struct as the one declaration of a CPU&lt;-&gt;GPU contract (internals.md, "One
    /// contract to the GPU"). The rig's <c>gt generate</c> reads it and writes the other sides, which
    /// are committed and never edited: the HLSL at <see cref="HlslPath"/> and the C# at
    /// <see cref="CSharpPath"/> (the shader names and the field count). Its test fails when a
    /// generated file differs from what the declaration gives. Every instance field is a
    /// <see cref="Float4"/> (a std140 float4 each: the C# and HLSL offsets agree) named as its
    /// constant without the '_' and with a small first letter (<c>rangeOrigin</c> is <c>_RangeOrigin</c>).
    /// </summary>
    [AttributeUsage(AttributeTargets.Struct, Inherited = false)]
    internal sealed class GenerateHlslAttribute : Attribute
    {
        /// <param name="hlslPath">The generated member list, relative to the package root; the HLSL block that holds the constants includes it.</param>
        /// <param name="cSharpPath">The generated part of the struct, relative to the package root.</param>
        public GenerateHlslAttribute(string hlslPath, string cSharpPath)
        {
            HlslPath = hlslPath;
            CSharpPath = cSharpPath;
        }

        public string HlslPath { get; }
        public string CSharpPath { get; }
    }

    /// <summary>A contract field's meaning and update rate, written beside its HLSL declaration.</summary>
    [AttributeUsage(AttributeTargets.Field, Inherited = false)]
    internal sealed class HlslCommentAttribute : Attribute
    {
        public HlslCommentAttribute(string text) { Text = text; }
        public string Text { get; }
    }
}
