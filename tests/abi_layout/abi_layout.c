/* abi_layout.c: prints the layout of every public struct of coverage_axis.h as this platform's C
 * compiler lays it out, so that bindings (Rust, C#, Julia, Python) can compare their own struct
 * declarations with the header mechanically.
 *
 * Output format (stable; one record per line, fields separated by one space, sizes and offsets
 * in bytes, decimal):
 *   abi VERSION                           first line: CA_ABI_VERSION of the header
 *   struct NAME SIZEOF                    a struct, before its fields
 *   field NAME FIELD OFFSET SIZE          each field of that struct, in declaration order
 * Structs appear in header order. A field's ABI version is in the header's comment; the size a
 * caller of an earlier ABI passes as struct_size is the end of its last field, rounded up to the
 * struct's alignment.
 * usage: abi_layout            (prints to stdout, exit status 0) */
#include "coverage_axis.h"

#include <stddef.h>
#include <stdio.h>

#define STRUCT(T) printf("struct %s %zu\n", #T, sizeof(T))
#define FIELD(T, F) printf("field %s %s %zu %zu\n", #T, #F, offsetof(T, F), sizeof(((T*)0)->F))

int main(void) {
    printf("abi %d\n", CA_ABI_VERSION);
    STRUCT(ca_context_desc);
    FIELD(ca_context_desc, struct_size);
    FIELD(ca_context_desc, alloc);
    FIELD(ca_context_desc, free);
    FIELD(ca_context_desc, alloc_user);
    FIELD(ca_context_desc, log);
    FIELD(ca_context_desc, log_user);
    FIELD(ca_context_desc, progress);
    FIELD(ca_context_desc, progress_user);
    FIELD(ca_context_desc, threads);
    FIELD(ca_context_desc, progress_interval_s);
    FIELD(ca_context_desc, time_limit_s);
    STRUCT(ca_surface_view);
    FIELD(ca_surface_view, struct_size);
    FIELD(ca_surface_view, positions);
    FIELD(ca_surface_view, vertex_count);
    FIELD(ca_surface_view, position_stride);
    FIELD(ca_surface_view, triangles);
    FIELD(ca_surface_view, triangle_count);
    FIELD(ca_surface_view, triangle_stride);
    FIELD(ca_surface_view, normals);
    FIELD(ca_surface_view, normal_stride);
    FIELD(ca_surface_view, point_normals);
    FIELD(ca_surface_view, normal_count);
    STRUCT(ca_candidate_options);
    FIELD(ca_candidate_options, struct_size);
    FIELD(ca_candidate_options, generator);
    FIELD(ca_candidate_options, cover_samples);
    FIELD(ca_candidate_options, voronoi_samples);
    FIELD(ca_candidate_options, random_candidates);
    FIELD(ca_candidate_options, seed);
    FIELD(ca_candidate_options, connect_samples);
    FIELD(ca_candidate_options, reserved_abi2_tail);
    FIELD(ca_candidate_options, volumetric_only);
    STRUCT(ca_select_options);
    FIELD(ca_select_options, struct_size);
    FIELD(ca_select_options, dilation);
    FIELD(ca_select_options, delta);
    FIELD(ca_select_options, scale);
    FIELD(ca_select_options, solver);
    FIELD(ca_select_options, time_limit_s);
    FIELD(ca_select_options, skip_uncoverable);
    FIELD(ca_select_options, ignorable_samples);
    FIELD(ca_select_options, forced_in);
    FIELD(ca_select_options, forced_out);
    FIELD(ca_select_options, target_count);
    FIELD(ca_select_options, target_tolerance);
    FIELD(ca_select_options, divide_threshold);
    FIELD(ca_select_options, effort);
    FIELD(ca_select_options, target_error);
    FIELD(ca_select_options, probe_fit);
    FIELD(ca_select_options, ignorable_samples_count);
    FIELD(ca_select_options, forced_in_count);
    FIELD(ca_select_options, forced_out_count);
    STRUCT(ca_select_stats);
    FIELD(ca_select_stats, struct_size);
    FIELD(ca_select_stats, proven_optimal);
    FIELD(ca_select_stats, solver);
    FIELD(ca_select_stats, objective);
    FIELD(ca_select_stats, lower_bound);
    FIELD(ca_select_stats, gap);
    FIELD(ca_select_stats, delta_absolute);
    FIELD(ca_select_stats, time_reduce_s);
    FIELD(ca_select_stats, time_solve_s);
    FIELD(ca_select_stats, time_total_s);
    FIELD(ca_select_stats, rows_before);
    FIELD(ca_select_stats, cols_before);
    FIELD(ca_select_stats, rows_after);
    FIELD(ca_select_stats, cols_after);
    FIELD(ca_select_stats, forced);
    FIELD(ca_select_stats, components);
    FIELD(ca_select_stats, probes);
    FIELD(ca_select_stats, parts);
    FIELD(ca_select_stats, scale_used);
    FIELD(ca_select_stats, time_coverage_s);
    FIELD(ca_select_stats, cbc_components);
    FIELD(ca_select_stats, rowgen_rounds);
    FIELD(ca_select_stats, hd_reached);
    STRUCT(ca_connect_options);
    FIELD(ca_connect_options, struct_size);
    FIELD(ca_connect_options, method);
    FIELD(ca_connect_options, remove_outside);
    FIELD(ca_connect_options, fill_holes);
    FIELD(ca_connect_options, reconnect);
    FIELD(ca_connect_options, fit);
    FIELD(ca_connect_options, fit_iterations);
    STRUCT(ca_skeleton_stats);
    FIELD(ca_skeleton_stats, struct_size);
    FIELD(ca_skeleton_stats, vertices);
    FIELD(ca_skeleton_stats, edges);
    FIELD(ca_skeleton_stats, faces);
    FIELD(ca_skeleton_stats, components);
    FIELD(ca_skeleton_stats, isolated);
    FIELD(ca_skeleton_stats, betti1);
    FIELD(ca_skeleton_stats, time_s);
    FIELD(ca_skeleton_stats, method);
    FIELD(ca_skeleton_stats, fit_time_s);
    FIELD(ca_skeleton_stats, fit_error_before);
    FIELD(ca_skeleton_stats, fit_error_after);
    FIELD(ca_skeleton_stats, fit_uncovered);
    FIELD(ca_skeleton_stats, fitted);
    FIELD(ca_skeleton_stats, genus);
    FIELD(ca_skeleton_stats, thin_handles);
    FIELD(ca_skeleton_stats, medial_balls);
    FIELD(ca_skeleton_stats, surface_balls);
    FIELD(ca_skeleton_stats, open_parts);
    STRUCT(ca_skeleton_view);
    FIELD(ca_skeleton_view, struct_size);
    FIELD(ca_skeleton_view, centers);
    FIELD(ca_skeleton_view, radii);
    FIELD(ca_skeleton_view, vertex_count);
    FIELD(ca_skeleton_view, edges);
    FIELD(ca_skeleton_view, edge_count);
    FIELD(ca_skeleton_view, faces);
    FIELD(ca_skeleton_view, face_count);
    STRUCT(ca_evaluate_options);
    FIELD(ca_evaluate_options, struct_size);
    FIELD(ca_evaluate_options, surface_samples);
    FIELD(ca_evaluate_options, envelope_samples);
    FIELD(ca_evaluate_options, seed);
    STRUCT(ca_evaluation);
    FIELD(ca_evaluation, struct_size);
    FIELD(ca_evaluation, hd_surface_to_recon);
    FIELD(ca_evaluation, mean_surface_to_recon);
    FIELD(ca_evaluation, hd_recon_to_surface);
    FIELD(ca_evaluation, mean_recon_to_surface);
    FIELD(ca_evaluation, hd_two_sided);
    FIELD(ca_evaluation, diagonal);
    FIELD(ca_evaluation, surface_samples_used);
    FIELD(ca_evaluation, envelope_samples_used);
    FIELD(ca_evaluation, time_s);

    STRUCT(ca_correspondence_options);
    FIELD(ca_correspondence_options, struct_size);
    FIELD(ca_correspondence_options, smoothing);

    STRUCT(ca_rig_options);
    FIELD(ca_rig_options, struct_size);
    FIELD(ca_rig_options, root);
    FIELD(ca_rig_options, max_joints);
    FIELD(ca_rig_options, joint_spacing);
    FIELD(ca_rig_options, min_branch);
    FIELD(ca_rig_options, smoothing);
    STRUCT(ca_proxy_options);
    FIELD(ca_proxy_options, struct_size);
    FIELD(ca_proxy_options, shapes);
    FIELD(ca_proxy_options, mode);
    FIELD(ca_proxy_options, count);
    FIELD(ca_proxy_options, surface_samples);
    FIELD(ca_proxy_options, evaluate_samples);
    FIELD(ca_proxy_options, volume_samples);
    FIELD(ca_proxy_options, seed);
    STRUCT(ca_proxy_stats);
    FIELD(ca_proxy_stats, struct_size);
    FIELD(ca_proxy_stats, hd_surface_to_proxies);
    FIELD(ca_proxy_stats, mean_surface_to_proxies);
    FIELD(ca_proxy_stats, hd_proxies_to_surface);
    FIELD(ca_proxy_stats, mean_proxies_to_surface);
    FIELD(ca_proxy_stats, hd_two_sided);
    FIELD(ca_proxy_stats, outside_bound);
    FIELD(ca_proxy_stats, skeleton_outside);
    FIELD(ca_proxy_stats, union_volume);
    FIELD(ca_proxy_stats, outside_volume);
    FIELD(ca_proxy_stats, radius_change);
    FIELD(ca_proxy_stats, diagonal);
    FIELD(ca_proxy_stats, candidates);
    FIELD(ca_proxy_stats, surface_cells);
    FIELD(ca_proxy_stats, time_s);
    STRUCT(ca_proxy_placement);
    FIELD(ca_proxy_placement, struct_size);
    FIELD(ca_proxy_placement, kind);
    FIELD(ca_proxy_placement, center);
    FIELD(ca_proxy_placement, rotation);
    FIELD(ca_proxy_placement, axis);
    FIELD(ca_proxy_placement, radius_top);
    FIELD(ca_proxy_placement, radius_bottom);
    FIELD(ca_proxy_placement, height);
    FIELD(ca_proxy_placement, half_extents);
    STRUCT(ca_skin_view);
    FIELD(ca_skin_view, struct_size);
    FIELD(ca_skin_view, joint_count);
    FIELD(ca_skin_view, parents);
    FIELD(ca_skin_view, inverse_bind);
    FIELD(ca_skin_view, vertex_count);
    FIELD(ca_skin_view, influences);
    FIELD(ca_skin_view, vertex_joints);
    FIELD(ca_skin_view, vertex_weights);
    STRUCT(ca_bone_collider_options);
    FIELD(ca_bone_collider_options, struct_size);
    FIELD(ca_bone_collider_options, mode);
    FIELD(ca_bone_collider_options, shapes);
    FIELD(ca_bone_collider_options, min_share);
    FIELD(ca_bone_collider_options, min_size);
    FIELD(ca_bone_collider_options, skip_joints);
    FIELD(ca_bone_collider_options, skip_count);
    FIELD(ca_bone_collider_options, surface_samples);
    FIELD(ca_bone_collider_options, evaluate_samples);
    FIELD(ca_bone_collider_options, seed);
    STRUCT(ca_bone_collider_stats);
    FIELD(ca_bone_collider_stats, struct_size);
    FIELD(ca_bone_collider_stats, contained_fraction);
    FIELD(ca_bone_collider_stats, union_volume);
    FIELD(ca_bone_collider_stats, outside_volume);
    FIELD(ca_bone_collider_stats, neighbour_overlap);
    FIELD(ca_bone_collider_stats, joints_with_collider);
    FIELD(ca_bone_collider_stats, joints_skipped);
    FIELD(ca_bone_collider_stats, time_s);
    return 0;
}
