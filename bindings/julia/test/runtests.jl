# runtests.jl: the package's tests, `julia --project=bindings/julia -e 'using Pkg; Pkg.test()'` with
# COVERAGE_AXIS_LIBRARY set to the built library (build/libcoverage_axis.so). Julia is not packaged
# in Debian 12, so this project's CTest checks only the struct layouts (julia_layout).
using CoverageAxis
using Test

# n points on the unit sphere (a Fibonacci spiral) as a 3×n matrix; each is its own outward normal.
function sphere_points(n)
    golden = π * (3 - sqrt(5))
    p = Matrix{Float64}(undef, 3, n)
    for i in 0:n-1
        z = 1 - 2 * (i + 0.5) / n
        r = sqrt(1 - z^2)
        p[:, i+1] = [r * cos(golden * i), r * sin(golden * i), z]
    end
    p
end

# The error a call throws, or nothing.
caught(f) = try f(); nothing catch e; e end

const BOX_V = Float64[0 2 2 0 0 2 2 0; 0 0 1 1 0 0 1 1; 0 0 0 0 1 1 1 1]
const BOX_F = UInt32[0 0 4 4 0 0 1 1 2 2 3 3; 2 3 5 6 1 5 2 6 3 7 0 4; 1 2 6 7 5 4 6 5 7 6 4 7]

@testset "CoverageAxis" begin
    @test CoverageAxis.abi_version() >= CoverageAxis.ABI_VERSION
    ctx = Context(threads=1)

    @testset "a box: balls on its medial axis" begin
        set = candidates(ctx, BOX_V, BOX_F; cover_samples=400, voronoi_samples=800)
        skel = connect(ctx, set, select(ctx, set))
        @test length(skel) > 0
        @test all(0.0 .<= centers(skel)[1, :] .<= 2.0)
        @test stats(skel).vertices == length(skel)
    end

    @testset "wrong lengths are errors before the call" begin
        points = sphere_points(400)
        for n in (10, 399)
            e = caught(() -> candidates(ctx, points; normals=points[:, 1:n]))
            @test e isa CoverageAxisError
            @test e.status == CoverageAxis.CA_ERROR_INVALID_INPUT
            @test occursin("normals: $n for 400 points", e.message)
        end
        set = candidates(ctx, points; normals=points, cover_samples=100, voronoi_samples=400)
        e = caught(() -> select(ctx, set; forced_in=zeros(UInt8, length(set) - 1)))
        @test e isa CoverageAxisError && e.status == CoverageAxis.CA_ERROR_INVALID_INPUT && occursin("forced_in", e.message)
        e = caught(() -> select(ctx, set; ignorable_samples=zeros(UInt8, CoverageAxis.sample_count(set) + 1)))
        @test e isa CoverageAxisError && e.status == CoverageAxis.CA_ERROR_INVALID_INPUT
        forced = zeros(UInt8, length(set))
        forced[1] = 1
        @test UInt32(0) in indices(select(ctx, set; forced_in=forced))
    end
    close(ctx)
end
