using System;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// The rig's camera: the 36 floats of the <c>RigCamera</c> cbuffer (Tools~/rig/README.md, "Descriptor bindings", binding 1).
    /// Matrices are built in double, row-major in maths (<c>clip = M * p</c>), and written column
    /// after column, which is how HLSL's default column_major packing reads them.
    /// A Unity camera's: the world is Unity's, left-handed (a camera looking along +Z with +Y up has
    /// +X on its right), camera space right-handed (looking down -z, Camera.worldToCameraMatrix),
    /// clip space as HLSL/D3D has it, y up (the harness flips the viewport), and reversed depth as
    /// Unity draws on Vulkan (UNITY_REVERSED_Z: near 1, far 0; the harness's default --depth
    /// reversed). So the harness's picture is what Unity shows, and a triangle's winding in it is
    /// the one Unity's culling sees.
    /// </summary>
    sealed class RigCamera
    {
        public double[,] ObjectToWorld = Identity();
        public double[,] WorldToClip = Identity();
        public double[] Position = new double[3];
        public double[] LightDirection = { -0.4, 0.8, -0.45 };
        public int Width = 1024, Height = 768;

        /// <summary>
        /// Perspective camera at <paramref name="eye"/> looking at <paramref name="target"/>, +Y up
        /// (+Z up when looking straight up or down), as Unity's Transform.LookAt turns a camera.
        /// Depth is reversed: float depth then keeps its relative precision (~6e-8 of the distance)
        /// out to the horizon; the conventional 0..1 keeps only ~6e-8 z^2 / near, kilometres at
        /// 500 km with near = 5 cm, so a far ridge's hidden faces would show through its front.
        /// </summary>
        public static RigCamera LookAt(double[] eye, double[] target, double fovYDegrees, int width, int height,
                                       double near, double far, double[,] objectToWorld)
        {
            var f = Normalize(Sub(target, eye));
            double[] up = Math.Abs(f[1]) > 0.99 ? new[] { 0.0, 0.0, 1.0 } : new[] { 0.0, 1.0, 0.0 };
            // Left-handed world: right = up x forward (Quaternion.LookRotation's x axis).
            var r = Normalize(Cross(up, f));
            var u = Cross(f, r);
            var view = new double[,]
            {
                { r[0], r[1], r[2], -Dot(r, eye) },
                { u[0], u[1], u[2], -Dot(u, eye) },
                { -f[0], -f[1], -f[2], Dot(f, eye) },
                { 0, 0, 0, 1 },
            };
            double t = 1.0 / Math.Tan(fovYDegrees * Math.PI / 360.0), aspect = (double)width / height;
            // Camera space (looking down -z) to D3D-style clip: y up (the harness's viewport has a
            // negative height, as internals.md says), depth reversed: z / w = 1 at near, 0 at far.
            double zz = near / (far - near), zw = near * far / (far - near);
            var proj = new double[,]
            {
                { t / aspect, 0, 0, 0 },
                { 0, t, 0, 0 },
                { 0, 0, zz, zw },
                { 0, 0, -1, 0 },
            };
            return new RigCamera
            {
                ObjectToWorld = objectToWorld,
                WorldToClip = Mul(proj, view),
                Position = (double[])eye.Clone(),
                Width = width,
                Height = height,
            };
        }

        /// <summary>Object to clip, in double (what <see cref="Pack"/> rounds to float).</summary>
        public double[,] ObjectToClip() => Mul(WorldToClip, ObjectToWorld);

        public static double[,] Scale(double x, double y, double z) =>
            new double[,] { { x, 0, 0, 0 }, { 0, y, 0, 0 }, { 0, 0, z, 0 }, { 0, 0, 0, 1 } };

        /// <summary>The cbuffer's floats: ObjectToClip, ObjectToWorld, CameraPosition, ScreenSize, LightDirection.</summary>
        public float[] Pack()
        {
            var r = new float[16 + 16 + 4 + 4 + 4];
            WriteColumns(ObjectToClip(), r, 0);
            WriteColumns(ObjectToWorld, r, 16);
            r[32] = (float)Position[0]; r[33] = (float)Position[1]; r[34] = (float)Position[2]; r[35] = 1;
            r[36] = Width; r[37] = Height; r[38] = 1f / Width; r[39] = 1f / Height;
            var l = Normalize(LightDirection);
            r[40] = (float)l[0]; r[41] = (float)l[1]; r[42] = (float)l[2]; r[43] = 0;
            return r;
        }

        /// <summary>Object-space point to pixel coordinates, NDC depth (reversed: 1 at near) and w, for error measures in pixels.</summary>
        public double[] ToPixels(double[] objectPoint)
        {
            var m = ObjectToClip();
            var c = new double[4];
            for (int i = 0; i < 4; i++)
                c[i] = m[i, 0] * objectPoint[0] + m[i, 1] * objectPoint[1] + m[i, 2] * objectPoint[2] + m[i, 3];
            // Pixel rows count down from the top; clip y is up.
            return new[] { (c[0] / c[3] * 0.5 + 0.5) * Width, (0.5 - c[1] / c[3] * 0.5) * Height, c[2] / c[3], c[3] };
        }

        /// <summary>True when the object point is in front of the camera and inside the screen rectangle.</summary>
        public bool Visible(double[] objectPoint)
        {
            var c = Clip(objectPoint);
            return c[3] > 0 && Math.Abs(c[0]) <= c[3] && Math.Abs(c[1]) <= c[3];
        }

        /// <summary>
        /// The largest number of pixels one object unit covers at the point, in any direction: the
        /// largest singular value of the Jacobian of object -> pixels (Core's
        /// TessellationPolicy.PixelsPerUnit, in double). +infinity at or behind the eye plane.
        /// </summary>
        public double PixelsPerUnit(double[] objectPoint)
        {
            var c = Clip(objectPoint);
            var m = _objectToClip;
            if (!(c[3] > 0)) return double.PositiveInfinity;
            double sx = c[0] / c[3], sy = c[1] / c[3], hx = 0.5 * Width / c[3], hy = 0.5 * Height / c[3];
            var r0 = new double[3];
            var r1 = new double[3];
            for (int k = 0; k < 3; k++)
            {
                r0[k] = (m[0, k] - sx * m[3, k]) * hx;
                r1[k] = (m[1, k] - sy * m[3, k]) * hy;
            }
            double a = Dot(r0, r0), b = Dot(r0, r1), cc = Dot(r1, r1), h = 0.5 * (a - cc);
            return Math.Sqrt(0.5 * (a + cc) + Math.Sqrt(h * h + b * b));
        }

        /// <summary>Object -> clip as Core's Float4x4 (what the shader gets, rounded to float).</summary>
        public Float4x4 ObjectToClipFloat()
        {
            var m = Mul(WorldToClip, ObjectToWorld);
            return Float4x4.FromRows(
                (float)m[0, 0], (float)m[0, 1], (float)m[0, 2], (float)m[0, 3],
                (float)m[1, 0], (float)m[1, 1], (float)m[1, 2], (float)m[1, 3],
                (float)m[2, 0], (float)m[2, 1], (float)m[2, 2], (float)m[2, 3],
                (float)m[3, 0], (float)m[3, 1], (float)m[3, 2], (float)m[3, 3]);
        }

        double[] Clip(double[] p)
        {
            var m = _objectToClip ??= Mul(WorldToClip, ObjectToWorld);
            var c = new double[4];
            for (int i = 0; i < 4; i++) c[i] = m[i, 0] * p[0] + m[i, 1] * p[1] + m[i, 2] * p[2] + m[i, 3];
            return c;
        }

        double[,] _objectToClip;

        static void WriteColumns(double[,] m, float[] dst, int at)
        {
            for (int col = 0; col < 4; col++)
                for (int row = 0; row < 4; row++)
                    dst[at + col * 4 + row] = (float)m[row, col];
        }

        static double[,] Identity() => Scale(1, 1, 1);

        static double[,] Mul(double[,] a, double[,] b)
        {
            var r = new double[4, 4];
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++)
                    for (int k = 0; k < 4; k++)
                        r[i, j] += a[i, k] * b[k, j];
            return r;
        }

        static double[] Sub(double[] a, double[] b) => new[] { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
        static double Dot(double[] a, double[] b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        static double[] Cross(double[] a, double[] b) =>
            new[] { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
        static double[] Normalize(double[] a)
        {
            double l = Math.Sqrt(Dot(a, a));
            return new[] { a[0] / l, a[1] / l, a[2] / l };
        }
    }
}
