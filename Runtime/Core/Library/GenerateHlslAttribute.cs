using System;
using System.Diagnostics;

namespace GregoryTerrain
{
    /// <summary>
    /// Marks a Core struct as the one declaration of a CPU&lt;-&gt;GPU contract (internals.md, "One
    /// contract to the GPU"). The rig's <c>gt generate</c> reads it and writes the other sides, which
    /// are committed and never edited: the HLSL at <see cref="HlslPath"/> and the C# at
    /// <see cref="CSharpPath"/> (the shader names and the field count). Every instance field is a
    /// <see cref="Float4"/> (a std140 float4 each: the C# and HLSL offsets agree) named as its
    /// constant without the '_' and with a small first letter (<c>rangeOrigin</c> is <c>_RangeOrigin</c>).
    /// Only the rig defines GT_CONTRACTS: Unity compiles every use of these attributes away.
    /// </summary>
    [Conditional("GT_CONTRACTS")]
    [AttributeUsage(AttributeTargets.Struct, Inherited = false)]
    internal sealed class GenerateHlslAttribute : Attribute
    {
        /// <param name="hlslPath">
        /// The generated HLSL, relative to the package root: the member list of a constants block
        /// (the block that holds the constants includes it), or with <see cref="Record"/> an HLSL
        /// struct of the same name for a structured buffer's element.
        /// </param>
        /// <param name="cSharpPath">The generated part of a constants struct, relative to the package root; null for a record.</param>
        public GenerateHlslAttribute(string hlslPath, string cSharpPath = null)
        {
            HlslPath = hlslPath;
            CSharpPath = cSharpPath;
        }

        public string HlslPath { get; }
        public string CSharpPath { get; }
        /// <summary>An element of a structured buffer, not constants set by name: an HLSL struct, no C# names.</summary>
        public bool Record { get; set; }
    }

    /// <summary>
    /// On the first of <see cref="Length"/> fields <c>stem0</c>, <c>stem1</c>, ...: in HLSL they are one
    /// array member, <c>float4 Name[Length]</c> (C# 9 in Unity has no fixed-size buffer of a struct).
    /// </summary>
    [Conditional("GT_CONTRACTS")]
    [AttributeUsage(AttributeTargets.Field, Inherited = false)]
    internal sealed class HlslArrayAttribute : Attribute
    {
        public HlslArrayAttribute(string name, int length) { Name = name; Length = length; }
        public string Name { get; }
        public int Length { get; }
    }

    /// <summary>A contract field's meaning and update rate, written beside its HLSL declaration.</summary>
    [Conditional("GT_CONTRACTS")]
    [AttributeUsage(AttributeTargets.Field, Inherited = false)]
    internal sealed class HlslCommentAttribute : Attribute
    {
        public HlslCommentAttribute(string text) { Text = text; }
        public string Text { get; }
    }
}
