// TestCoverageAxis.cs: tests of the C# binding. The layout check compares every struct of
// CoverageAxis.Native (Marshal.SizeOf / Marshal.OffsetOf) with the C layout printed by
// tests/abi_layout; fox.obj is skeletonized and compared with the .ma the CLI writes for it;
// errors, defaults, the Progress event, CancellationToken and lifetimes are checked.
// usage: mono TestCoverageAxis.exe ABI_LAYOUT_EXE CLI_EXE TEST_DATA_DIR
using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Text.RegularExpressions;
using System.Threading;
using CoverageAxis;

static class TestCoverageAxis
{
    static string layoutExe, cliExe, dataDir;
    static int passed, failed;

    static void Check(bool ok, string what)
    {
        if (!ok) throw new Exception("check failed: " + what);
    }

    static string Run(string exe, string args)
    {
        var p = Process.Start(new ProcessStartInfo(exe, args) { UseShellExecute = false, RedirectStandardOutput = true });
        var output = p.StandardOutput.ReadToEnd();
        p.WaitForExit();
        Check(p.ExitCode == 0, exe + " " + args + " exited " + p.ExitCode);
        return output;
    }

    // "ContextDesc" -> "ca_context_desc"
    static string CName(Type t)
    {
        return "ca" + Regex.Replace(t.Name, "([A-Z])", m => "_" + m.Value.ToLowerInvariant());
    }

    static void LayoutMatchesTheHeader()
    {
        var printed = new List<string>();
        foreach (var line in Run(layoutExe, "").Split('\n'))
            if (line.StartsWith("struct ") || line.StartsWith("field ")) printed.Add(line);
            else if (line.StartsWith("abi ")) Check(line == "abi " + Native.AbiVersion, "header " + line);
        var declared = new List<string>();
        foreach (var t in Native.Structs)
        {
            declared.Add("struct " + CName(t) + " " + Marshal.SizeOf(t));
            var fields = t.GetFields().OrderBy(f => (long)Marshal.OffsetOf(t, f.Name));
            foreach (var f in fields)
                declared.Add(string.Format("field {0} {1} {2} {3}", CName(t), f.Name, (long)Marshal.OffsetOf(t, f.Name),
                                           Marshal.SizeOf(f.FieldType)));
        }
        for (int i = 0; i < Math.Max(printed.Count, declared.Count); ++i)
        {
            var want = i < printed.Count ? printed[i] : "(nothing)";
            var got = i < declared.Count ? declared[i] : "(nothing)";
            Check(want == got, "C# layout line " + i + ": '" + got + "', the C compiler prints '" + want + "'");
        }
        Console.WriteLine("  {0} C# structs ({1} fields) match the printed layout", Native.Structs.Length,
                          declared.Count - Native.Structs.Length);
    }

    static Surface ReadObj(string path)
    {
        var v = new List<double>();
        var f = new List<uint>();
        foreach (var line in File.ReadAllLines(path))
        {
            var t = line.Split(new[] { ' ', '\t' }, StringSplitOptions.RemoveEmptyEntries);
            if (t.Length == 0) continue;
            if (t[0] == "v")
                for (int k = 1; k <= 3; ++k) v.Add(double.Parse(t[k], CultureInfo.InvariantCulture));
            else if (t[0] == "f")
            {
                var idx = t.Skip(1).Select(s => uint.Parse(s.Split('/')[0]) - 1).ToArray();
                for (int k = 1; k + 1 < idx.Length; ++k) f.AddRange(new[] { idx[0], idx[k], idx[k + 1] });
            }
        }
        return Surface.Mesh(v.ToArray(), f.ToArray());
    }

    static bool Close(double a, double b) { return Math.Abs(a - b) <= 1e-7 * Math.Max(Math.Abs(b), 1.0); }

    static void FoxMatchesTheCli()
    {
        var model = Path.Combine(dataDir, "fox.obj");
        var ma = Path.Combine(Path.GetTempPath(), "coverage_axis_cs_" + Process.GetCurrentProcess().Id + ".ma");
        Run(cliExe, "\"" + model + "\" -o \"" + ma + "\" --quiet");
        var lines = File.ReadAllLines(ma);
        File.Delete(ma);
        var counts = lines[0].Split(' ').Select(int.Parse).ToArray();
        var balls = lines.Where(l => l.StartsWith("v ")).Select(l => l.Substring(2).Split(' ')
            .Select(s => double.Parse(s, CultureInfo.InvariantCulture)).ToArray()).ToArray();
        Check(balls.Length == counts[0] && balls.Length > 10, "the CLI's .ma has " + balls.Length + " balls");

        var surface = ReadObj(model);
        using (var ctx = new Context(threads: 2))
        using (var skeleton = ctx.Skeletonize(surface))
        {
            Check(skeleton.Count == balls.Length, skeleton.Count + " balls, the CLI " + balls.Length);
            var c = skeleton.Centers;
            var r = skeleton.Radii;
            for (int i = 0; i < balls.Length; ++i)
                Check(Close(c[3 * i], balls[i][0]) && Close(c[3 * i + 1], balls[i][1]) && Close(c[3 * i + 2], balls[i][2])
                      && Close(r[i], balls[i][3]), "ball " + i + " differs from the CLI's");
            Check(skeleton.Edges.Length / 2 == counts[1] && skeleton.Faces.Length / 3 == counts[2], "edge/face counts");
            Check((int)skeleton.Stats.vertices == balls.Length, "stats.vertices");
            var e = ctx.Evaluate(surface, skeleton, new EvaluateOptions { SurfaceSamples = 2000, EnvelopeSamples = 2000 });
            Check(e.hd_two_sided > 0 && e.hd_two_sided < 20, "two-sided Hausdorff " + e.hd_two_sided);
            Console.WriteLine("  fox: {0} balls, {1} edges, {2} faces match the CLI", balls.Length, counts[1], counts[2]);
        }
    }

    static void DefaultsComeFromTheLibrary()
    {
        var s = new SelectOptions();
        Check(s.Delta == 0.02 && s.Scale == 1.5 && s.Solver == Solver.Exact, "select defaults");
        Check(new CandidateOptions().CoverSamples == 1500, "cover_samples default");
        Check(new ConnectOptions().Method == ConnectMethod.Auto, "connect default");
        Check(new EvaluateOptions().SurfaceSamples == 30000, "evaluate default");
    }

    static void ErrorsCarryStatusAndMessage()
    {
        using (var ctx = new Context())
        {
            try { ctx.Candidates(Surface.Mesh(new double[0], new uint[0])); Check(false, "empty surface accepted"); }
            catch (CoverageAxisException e) { Check(e.Status == Status.DegenerateInput && e.Message.Length > 0, e.Message); }
            var tri = Surface.Mesh(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new uint[] { 0, 1, 7 });
            try { ctx.Candidates(tri); Check(false, "bad index accepted"); }
            catch (CoverageAxisException e) { Check(e.Status == Status.InvalidInput, e.Message); }
        }
        try { new Context(threads: -1); Check(false, "threads -1 accepted"); }
        catch (CoverageAxisException e) { Check(e.Status == Status.InvalidArgument, e.Message); }
    }

    // n points on the unit sphere (a Fibonacci spiral), x y z each; each is its own outward normal.
    static double[] SpherePoints(int n)
    {
        var p = new double[3 * n];
        double golden = Math.PI * (3 - Math.Sqrt(5));
        for (int i = 0; i < n; ++i)
        {
            double z = 1 - 2 * (i + 0.5) / n, r = Math.Sqrt(1 - z * z);
            p[3 * i] = r * Math.Cos(golden * i);
            p[3 * i + 1] = r * Math.Sin(golden * i);
            p[3 * i + 2] = z;
        }
        return p;
    }

    static void LengthsAreCheckedBeforeTheCall()
    {
        var points = SpherePoints(400);
        using (var ctx = new Context(threads: 1))
        {
            foreach (int n in new[] { 10, 399, 401 })
            {
                var normals = SpherePoints(n);
                try { ctx.Candidates(Surface.Points(points, normals)); Check(false, n + " normals accepted for 400 points"); }
                catch (CoverageAxisException e)
                {
                    Check(e.Status == Status.InvalidInput && e.Message.Contains(n + " normals"), e.Message);
                }
            }
            var options = new CandidateOptions { CoverSamples = 100, VoronoiSamples = 400 };
            using (var set = ctx.Candidates(Surface.Points(points, points), options))
            {
                try { ctx.Select(set, new SelectOptions { ForcedIn = new byte[set.Count - 1] }); Check(false, "short mask accepted"); }
                catch (CoverageAxisException e) { Check(e.Status == Status.InvalidInput && e.Message.Contains("ForcedIn"), e.Message); }
                try
                {
                    ctx.Select(set, new SelectOptions { IgnorableSamples = new byte[set.SampleCount + 1] });
                    Check(false, "long mask accepted");
                }
                catch (CoverageAxisException e) { Check(e.Status == Status.InvalidInput, e.Message); }
                var forced = new byte[set.Count];
                forced[0] = 1;
                using (var selection = ctx.Select(set, new SelectOptions { ForcedIn = forced }))
                    Check(selection.Indices.Contains(0u), "the forced ball is selected");
            }
        }
    }

    static void TargetNotReachedKeepsTheBestSelection()
    {
        var surface = ReadObj(Path.Combine(dataDir, "fox.obj"));
        using (var ctx = new Context())
        using (var set = ctx.Candidates(surface, new CandidateOptions { CoverSamples = 300 }))
        {
            try
            {
                // a coarse bisection (default 1e-4): fewer probes, and no check depends on it
                ctx.Select(set, new SelectOptions { TargetError = 1e-4, TargetTolerance = 1e-2 });
                Check(false, "an unreachable target error returned success");
            }
            catch (TargetNotReachedException e)
            {
                Check(e.Status == Status.TargetNotReached && e.Message.Contains("not reached"), e.Message);
                using (var best = e.Selection)
                {
                    Check(best.Count > 0 && best.Stats.hd_reached > 1e-4, "the best selection is carried");
                    using (var sk = ctx.Connect(set, best)) Check(sk.Count == best.Count, "it connects");
                }
            }
        }
    }

    static void ProgressEventAndCancellation()
    {
        var surface = ReadObj(Path.Combine(dataDir, "fox.obj"));
        var small = new CandidateOptions { CoverSamples = 300 };
        using (var ctx = new Context())
        {
            var stages = new HashSet<string>();
            EventHandler<ProgressEventArgs> record = (o, e) => { stages.Add(e.Stage); Check(e.Fraction >= 0 && e.Fraction <= 1, "fraction"); };
            ctx.Progress += record;
            ctx.Candidates(surface, small).Dispose();
            Check(stages.Contains("sampling"), "progress stages: " + string.Join(",", stages));
            ctx.Progress -= record;

            EventHandler<ProgressEventArgs> stop = (o, e) => { e.Cancel = true; };
            ctx.Progress += stop;
            try { ctx.Candidates(surface, small); Check(false, "cancel from the event ignored"); }
            catch (CoverageAxisException e) { Check(e.Status == Status.Cancelled, e.Message); }
            ctx.Progress -= stop;

            using (var cts = new CancellationTokenSource())
            {
                // cancelled from another thread while the call runs (the event waits for that
                // thread, so the library sees the request at its next update)
                bool sent = false;
                EventHandler<ProgressEventArgs> cancelOnce = (o, e) =>
                {
                    if (sent) return;
                    sent = true;
                    var t = new Thread(() => cts.Cancel());
                    t.Start();
                    t.Join();
                };
                ctx.Progress += cancelOnce;
                try { ctx.Candidates(surface, null, cts.Token); Check(false, "token cancellation ignored"); }
                catch (OperationCanceledException e) { Check(e.CancellationToken == cts.Token, "the token"); }
                ctx.Progress -= cancelOnce;
            }
            using (var set = ctx.Candidates(surface, small)) Check(set.Count > 0, "a call after a cancelled one");
        }
    }

    static void ResultsOutliveContextAndSet()
    {
        var surface = ReadObj(Path.Combine(dataDir, "fox.obj"));
        Selection selection;
        Skeleton skeleton;
        int candidates;
        using (var ctx = new Context())
        using (var set = ctx.Candidates(surface, new CandidateOptions { CoverSamples = 300 }))
        {
            candidates = set.Count;
            selection = ctx.Select(set, new SelectOptions { Solver = Solver.Greedy });
            skeleton = ctx.Connect(set, selection);
        }
        using (selection)
        using (skeleton)
        {
            Check(selection.Indices.All(i => i < candidates) && selection.Indices.Length == selection.Count, "indices");
            Check(selection.DilatedRadii.Zip(selection.Radii, (d, r) => d > r).All(x => x), "dilated radii");
            Check((int)selection.Stats.objective == selection.Count, "stats.objective");
            Check(skeleton.Count == selection.Count, "skeleton size");
        }
    }

    static void RigMatchesTheCli()
    {
        var surface = ReadObj(Path.Combine(dataDir, "fox.obj"));
        using (var ctx = new Context())
        using (var skeleton = ctx.Skeletonize(surface))
        using (var c = ctx.Correspond(surface, skeleton))
        using (var rig = ctx.Rig(surface, skeleton))
        {
            var w = c.Weights;
            Check(c.Count * 3 == surface.Positions.Length, "one correspondence per vertex");
            bool sums = true;
            for (int i = 0; i < c.Count; ++i) sums &= Math.Abs(w[4 * i] + w[4 * i + 1] + w[4 * i + 2] + w[4 * i + 3] - 1) < 1e-12;
            Check(sums, "ball weights sum to 1");
            Check(c.Balls.All(b => b < skeleton.Count), "balls in range");
            var parents = rig.Parents;
            Check(parents[0] == -1 && Enumerable.Range(1, parents.Length - 1).All(j => parents[j] >= 0 && parents[j] < j),
                  "parents before children");
            Check(rig.VertexCount * 3 == surface.Positions.Length, "joint weights per vertex");
            var tmp = Path.Combine(Path.GetTempPath(), "coverage_axis_cs_rig_" + System.Diagnostics.Process.GetCurrentProcess().Id);
            var report = Run(cliExe, "\"" + Path.Combine(dataDir, "fox.obj") + "\" -o \"" + tmp + ".ma\" --rig \"" + tmp +
                                     ".glb\" --json");
            var want = "\"rig\":{\"joints\":" + rig.Count + ",\"branches\":" + rig.BranchCount + "}";
            Check(report.Contains(want), "the CLI's report has " + want);
            try { ctx.Rig(surface, skeleton, new RigOptions { MaxJoints = 0 }); Check(false, "max_joints 0 refused"); }
            catch (CoverageAxisException e) { Check(e.Status == Status.InvalidArgument, "max_joints 0: InvalidArgument"); }
        }
    }

    // min over t of |x - c(t)| - r(t), convex in t: ternary search (the test's own capsule distance)
    static double CapsuleDistance(double[] c, double[] r, int i, double[] x)
    {
        Func<double, double> f = t =>
        {
            double s = 0;
            for (int k = 0; k < 3; ++k)
            {
                double d = x[k] - (c[6 * i + k] + t * (c[6 * i + 3 + k] - c[6 * i + k]));
                s += d * d;
            }
            return Math.Sqrt(s) - (r[2 * i] + t * (r[2 * i + 1] - r[2 * i]));
        };
        double lo = 0, hi = 1;
        for (int it = 0; it < 100; ++it)
        {
            double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
            if (f(m1) <= f(m2)) hi = m2; else lo = m1;
        }
        return Math.Min(f(0.5 * (lo + hi)), Math.Min(f(0), f(1)));
    }

    static void ConservativeProxiesHoldTheVertices()
    {
        var surface = ReadObj(Path.Combine(dataDir, "fox.obj"));
        var positions = File.ReadAllLines(Path.Combine(dataDir, "fox.obj")).Where(l => l.StartsWith("v "))
            .Select(l => l.Substring(2).Split(new[] { ' ' }, StringSplitOptions.RemoveEmptyEntries)
            .Select(t => double.Parse(t, CultureInfo.InvariantCulture)).ToArray()).ToArray();
        using (var ctx = new Context(threads: 2))
        using (var set = ctx.Candidates(surface, new CandidateOptions { CoverSamples = 400 }))
        using (var selection = ctx.Select(set))
        using (var skeleton = ctx.Connect(set, selection))
        {
            var options = new ProxyOptions { Mode = ProxyMode.Conservative, Count = 6, EvaluateSamples = 2000, VolumeSamples = 5000 };
            Check(new ProxyOptions().Mode == ProxyMode.Inscribed && new ProxyOptions().Count == 16, "proxy defaults");
            using (var proxies = ctx.Proxies(set, skeleton, options))
            {
                Check(proxies.Count >= 1 && proxies.Count <= 6, proxies.Count + " proxies");
                Check(proxies.IsCapsule.Length == proxies.Count, "kinds");
                var c = proxies.Centers;
                var r = proxies.Radii;
                foreach (var x in positions)
                {
                    double best = double.PositiveInfinity;
                    for (int i = 0; i < proxies.Count; ++i) best = Math.Min(best, CapsuleDistance(c, r, i, x));
                    Check(best <= 1e-9, "a vertex outside every proxy (" + best + ")");
                }
                Check(proxies.Stats.hd_two_sided > 0 && proxies.Stats.outside_volume > 0, "proxy stats");
            }
            try
            {
                ctx.Proxies(set, skeleton, new ProxyOptions { Count = 0 });
                Check(false, "a count of 0 was accepted");
            }
            catch (CoverageAxisException e)
            {
                Check(e.Status == Status.InvalidArgument && e.Message.Contains("count"), "count 0: " + e.Message);
            }
        }
    }

    // A 2 x 1 x 1 box: its x = 0 end weighted to joint 0, its x = 2 end to joint 1 (turned about z
    // and moved by its inverse bind); each collider holds its half's corners in its joint's frame.
    static void BoneCollidersHoldTheirParts()
    {
        var surface = new Surface {
            Positions = new double[] { 0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0, 0, 0, 1, 2, 0, 1, 2, 1, 1, 0, 1, 1 },
            Triangles = new uint[] { 0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6,
                                     3, 0, 4, 3, 4, 7 } };
        var ib = new double[] { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, -1, 2, 0.5, 1 };
        var joints = new uint[16];
        var weights = new double[16];
        for (int v = 0; v < 8; ++v)
        {
            joints[2 * v] = surface.Positions[3 * v] == 0 ? 0u : 1u;
            joints[2 * v + 1] = 1 - joints[2 * v];
            weights[2 * v] = 1;
        }
        var skin = new Skin { Parents = new[] { -1, 0 }, InverseBind = ib, Influences = 2, VertexJoints = joints, VertexWeights = weights };
        using (var ctx = new Context(threads: 2))
        using (var set = ctx.Candidates(surface, new CandidateOptions { CoverSamples = 300, VoronoiSamples = 800 }))
        {
            Check(new BoneColliderOptions().Mode == ProxyMode.Conservative, "bone collider defaults");
            using (var bc = ctx.BoneColliders(set, skin))
            {
                Check(bc.Count == 2 && bc.Joints[0] == 0 && bc.Joints[1] == 1, bc.Count + " colliders");
                Check(bc.Stats.contained_fraction == 1.0 && bc.Contained[1] == 1.0, "containment");
                var colliders = bc.Colliders;
                for (int i = 0; i < bc.Count; ++i)
                {
                    var p = colliders[i];
                    double x0 = i == 0 ? 0 : 1;
                    for (int c = 0; c < 8; ++c)
                    {
                        double[] x = { x0 + (c & 1), (c >> 1) & 1, (c >> 2) & 1 };
                        var y = new double[3];
                        for (int r = 0; r < 3; ++r) y[r] = ib[16 * i + r] * x[0] + ib[16 * i + 4 + r] * x[1] + ib[16 * i + 8 + r] * x[2] + ib[16 * i + 12 + r];
                        var a = new double[3];
                        var b = new double[3];
                        for (int k = 0; k < 3; ++k)
                        {
                            a[k] = p.Center[k] - 0.5 * p.Height * p.Axis[k];
                            b[k] = p.Center[k] + 0.5 * p.Height * p.Axis[k];
                        }
                        double lo = 0, hi = 1;
                        Func<double, double> f = t => Math.Sqrt(Enumerable.Range(0, 3).Sum(k => Math.Pow(y[k] - (a[k] + t * (b[k] - a[k])), 2))) -
                                                      (p.RadiusBottom + t * (p.RadiusTop - p.RadiusBottom));
                        for (int it = 0; it < 200; ++it)
                        {
                            double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
                            if (f(m1) <= f(m2)) hi = m2; else lo = m1;
                        }
                        double d = Math.Min(Math.Min(f(0), f(1)), f(0.5 * (lo + hi)));
                        Check(d <= 1e-9, "joint " + i + " corner " + c + " outside by " + d);
                    }
                }
            }
            using (var bc = ctx.BoneColliders(set, skin, new BoneColliderOptions { SkipJoints = new uint[] { 0 } }))
                Check(bc.Count == 1 && bc.Joints[0] == 1, "skip list");
            try
            {
                ctx.BoneColliders(set, new Skin { Parents = new[] { 1, 0 }, InverseBind = ib, Influences = 2, VertexJoints = joints, VertexWeights = weights });
                Check(false, "a cycle was accepted");
            }
            catch (CoverageAxisException e)
            {
                Check(e.Status == Status.InvalidInput && e.Message.Contains("cycle"), "cycle: " + e.Message);
            }
        }
    }

    static void Test(string name, Action body)
    {
        try { body(); ++passed; Console.WriteLine("ok   " + name); }
        catch (Exception e) { ++failed; Console.WriteLine("FAIL " + name + ": " + e); }
    }

    static int Main(string[] args)
    {
        layoutExe = args[0]; cliExe = args[1]; dataDir = args[2];
        Test("layout matches the header", LayoutMatchesTheHeader);
        Test("defaults come from the library", DefaultsComeFromTheLibrary);
        Test("errors carry status and message", ErrorsCarryStatusAndMessage);
        Test("lengths are checked before the call", LengthsAreCheckedBeforeTheCall);
        Test("a target error not reached keeps the best selection", TargetNotReachedKeepsTheBestSelection);
        Test("fox matches the CLI", FoxMatchesTheCli);
        Test("progress event and cancellation", ProgressEventAndCancellation);
        Test("results outlive context and set", ResultsOutliveContextAndSet);
        Test("rig and correspondence match the CLI", RigMatchesTheCli);
        Test("conservative proxies hold the vertices", ConservativeProxiesHoldTheVertices);
        Test("bone colliders hold their parts", BoneCollidersHoldTheirParts);
        Console.WriteLine("{0} passed, {1} failed", passed, failed);
        return failed == 0 ? 0 : 1;
    }
}
