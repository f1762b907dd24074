// Skeletonize.cs: Context.Skeletonize at the defaults on a mesh given as plain numbers (the vertex
// and triangle counts, then x y z per vertex, then 0-based i j k per triangle), printing one ball
// per line, x y z r, exactly ("R" round-trip form). Run by skeletonize_agree.py, which compares
// every binding's skeletonize.
using System;
using System.Globalization;
using System.IO;
using CoverageAxis;

static class SkeletonizeMain
{
    static int Main(string[] args)
    {
        var numbers = File.ReadAllText(args[0]).Split((char[])null, StringSplitOptions.RemoveEmptyEntries);
        int at = 0;
        int nv = int.Parse(numbers[at++]), nf = int.Parse(numbers[at++]);
        var v = new double[3 * nv];
        for (int i = 0; i < v.Length; ++i) v[i] = double.Parse(numbers[at++], CultureInfo.InvariantCulture);
        var f = new uint[3 * nf];
        for (int i = 0; i < f.Length; ++i) f[i] = uint.Parse(numbers[at++]);
        using (var ctx = new Context())
        using (var skeleton = ctx.Skeletonize(Surface.Mesh(v, f)))
        {
            var c = skeleton.Centers;
            var r = skeleton.Radii;
            for (int i = 0; i < skeleton.Count; ++i)
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture, "{0:R} {1:R} {2:R} {3:R}",
                                                c[3 * i], c[3 * i + 1], c[3 * i + 2], r[i]));
        }
        return 0;
    }
}
