using System;

namespace GregoryTerrain
{
    /// <summary>
    /// A picture of a fit's error: the heightmap's samples binned into at most
    /// <see cref="MaxSide"/> x <see cref="MaxSide"/> cells, each keeping the largest
    /// |surface - sample| of its samples (height units). Cell (x, y) is <c>Cells[y * Width + x]</c>,
    /// y along the heightmap's rows, so it lies over the heightmap as a texture would.
    /// </summary>
    internal sealed class FitErrorMap
    {
        /// <summary>The most cells a side: 512, enough to see a patch's error at 256 patches a side.</summary>
        public const int MaxSide = 512;

        public int Width { get; }
        public int Height { get; }
        public float[] Cells { get; }
        readonly int sampleWidth, sampleHeight;

        public FitErrorMap(int sampleWidth, int sampleHeight)
        {
            if (sampleWidth < 1) throw new ArgumentException($"sampleWidth = {sampleWidth}, need at least 1.", nameof(sampleWidth));
            if (sampleHeight < 1) throw new ArgumentException($"sampleHeight = {sampleHeight}, need at least 1.", nameof(sampleHeight));
            this.sampleWidth = sampleWidth;
            this.sampleHeight = sampleHeight;
            Width = Math.Min(sampleWidth, MaxSide);
            Height = Math.Min(sampleHeight, MaxSide);
            Cells = new float[Width * Height];
        }

        /// <summary>Every cell back to 0 (a map reused for another net).</summary>
        public void Clear() => Array.Clear(Cells, 0, Cells.Length);

        /// <summary>The cell of sample (c, r).</summary>
        public int CellOf(int c, int r) => (int)((long)r * Height / sampleHeight) * Width + (int)((long)c * Width / sampleWidth);

        public void Add(int cell, double absError)
        {
            if (absError > Cells[cell]) Cells[cell] = (float)absError;
        }

        /// <summary>
        /// RGBA32 pixels (4 bytes per cell, the cells' order, so row 0 is the heightmap's row 0):
        /// black at 0, through blue and yellow, to red at <paramref name="fullScale"/> and above. A
        /// fixed scale (not each map's own maximum) keeps two fits comparable.
        /// </summary>
        public byte[] ToRgba32(double fullScale)
        {
            if (!(fullScale > 0) || double.IsInfinity(fullScale))
                throw new ArgumentException($"fullScale = {fullScale}, need a positive finite error.", nameof(fullScale));
            var px = new byte[4 * Cells.Length];
            for (int k = 0; k < Cells.Length; k++)
            {
                double t = Math.Min(1.0, Cells[k] / fullScale);
                // Three legs: black -> blue (0..1/3), blue -> yellow (1/3..2/3), yellow -> red (2/3..1).
                double r, g, b;
                if (t < 1.0 / 3) { r = 0; g = 0; b = 3 * t; }
                else if (t < 2.0 / 3) { double s = 3 * t - 1; r = s; g = s; b = 1 - s; }
                else { double s = 3 * t - 2; r = 1; g = 1 - s; b = 0; }
                px[4 * k] = (byte)Math.Round(255 * r);
                px[4 * k + 1] = (byte)Math.Round(255 * g);
                px[4 * k + 2] = (byte)Math.Round(255 * b);
                px[4 * k + 3] = 255;
            }
            return px;
        }
    }
}
