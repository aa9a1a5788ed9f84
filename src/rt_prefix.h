/*
 * rt_prefix.h - the core's global functions under the library's prefix.
 *
 * Every function the core exports is linked as rt_<name>, so it cannot
 * clash with a user's firmware; the source keeps the short names (as
 * zlib's Z_PREFIX does). real.h and fx.h, the roots of the internal
 * headers, include it; public headers do not, so a user's own names are
 * left alone. A new global function goes in this list: the symbol test
 * (tests/symbols.sh) fails on any global symbol without the prefix.
 */
#ifndef RT_PREFIX_H
#define RT_PREFIX_H

#define bvh_build                rt_bvh_build
#define bvh_tree_stats           rt_bvh_tree_stats
#define camera_column            rt_camera_column
#define camera_column_row        rt_camera_column_row
#define camera_next              rt_camera_next
#define camera_ray               rt_camera_ray
#define camera_row               rt_camera_row
#define camera_setup             rt_camera_setup
#define camera_sphere_box        rt_camera_sphere_box
#define camera_start_at_bounds   rt_camera_start_at_bounds
#define cone_init                rt_cone_init
#define cone_normal              rt_cone_normal
#define decimal_cmp              rt_decimal_cmp
#define decimal_exp2_bound       rt_decimal_exp2_bound
#define decimal_recip_scaled     rt_decimal_recip_scaled
#define fx_div                   rt_fx_div
#define fx_from_decimal          rt_fx_from_decimal
#define fx_mul64_call            rt_fx_mul64_call
#define fx_pow_unit              rt_fx_pow_unit
#define fx_recip                 rt_fx_recip
#define fx_recip_q31             rt_fx_recip_q31
#define fx_sincos_deg            rt_fx_sincos_deg
#define fx_sqrt                  rt_fx_sqrt
#define fx_tan_deg_wide          rt_fx_tan_deg_wide
#define fx_umul64_call           rt_fx_umul64_call
#define fx_unit3                 rt_fx_unit3
#define fx_unit3_narrow          rt_fx_unit3_narrow
#define fx_unit3_narrow_len      rt_fx_unit3_narrow_len
#define fx_wdiv                  rt_fx_wdiv
#define fx_wdiv_fx               rt_fx_wdiv_fx
#define fx_wdiv_int              rt_fx_wdiv_int
#define fx_wsqrt                 rt_fx_wsqrt
#define lex_count                rt_lex_count
#define lex_direction            rt_lex_direction
#define lex_direction_grid       rt_lex_direction_grid
#define lex_decimal              rt_lex_decimal
#define lex_fail                 rt_lex_fail
#define lex_fail_missing         rt_lex_fail_missing
#define lex_fail_tok             rt_lex_fail_tok
#define lex_is                   rt_lex_is
#define lex_next                 rt_lex_next
#define lex_next_on_line         rt_lex_next_on_line
#define lex_out_of_range         rt_lex_out_of_range
#define lex_over_capacity        rt_lex_over_capacity
#define lex_real                 rt_lex_real
#define lex_scalar               rt_lex_scalar
#define lex_scalar_scaled        rt_lex_scalar_scaled
#define lex_shine                rt_lex_shine
#define lex_start                rt_lex_start
#define lex_tok_decimal          rt_lex_tok_decimal
#define lex_vec3                 rt_lex_vec3
#define nff_read                 rt_nff_read
#define object_prim_surface      rt_object_prim_surface
#define plane_hit_inside         rt_plane_hit_inside
#define plane_init               rt_plane_init
#define polygon_init             rt_polygon_init
#define polygon_shading_normal   rt_polygon_shading_normal
#define prim_box                 rt_prim_box
#define r_from_decimal_scaled    rt_r_from_decimal_scaled
#define r_pow_float              rt_r_pow_float
#define ray_hit_cone             rt_ray_hit_cone
#define ray_hit_object           rt_ray_hit_object
#define ray_hit_plane            rt_ray_hit_plane
#define ray_hit_polygon          rt_ray_hit_polygon
#define ray_hit_sphere           rt_ray_hit_sphere
#define rd_blocks_closed         rt_rd_blocks_closed
#define rd_box                   rt_rd_box
#define rd_checker               rt_rd_checker
#define rd_difference_block      rt_rd_difference_block
#define rd_ellipsoid             rt_rd_ellipsoid
#define rd_end_block             rt_rd_end_block
#define rd_hyperboloid           rt_rd_hyperboloid
#define rd_hyperboloid2          rt_rd_hyperboloid2
#define rd_intersection_block    rt_rd_intersection_block
#define rd_marble                rt_rd_marble
#define rd_need_material         rt_rd_need_material
#define rd_paraboloid            rt_rd_paraboloid
#define rd_plane                 rt_rd_plane
#define rd_grid                  rt_rd_grid
#define rd_cross                 rt_rd_cross
#define rd_cut                   rt_rd_cut
#define rd_direction             rt_rd_direction
#define rd_pos                   rt_rd_pos
#define rd_pos3_grid             rt_rd_pos3_grid
#define rd_pos_decimal           rt_rd_pos_decimal
#define rd_pos3                  rt_rd_pos3
#define rd_quadcone              rt_rd_quadcone
#define rd_quadcylinder          rt_rd_quadcylinder
#define rd_quadric               rt_rd_quadric
#define rd_rotate                rt_rd_rotate
#define rd_scale                 rt_rd_scale
#define rd_sky                   rt_rd_sky
#define rd_sphere_solid          rt_rd_sphere_solid
#define rd_top_block             rt_rd_top_block
#define rd_torus                 rt_rd_torus
#define rd_transform_block       rt_rd_transform_block
#define rd_translate             rt_rd_translate
#define rd_union_block           rt_rd_union_block
#define scene_fold_stats         rt_scene_fold_stats
#define scene_nearest            rt_scene_nearest
#define scene_nearest_brute      rt_scene_nearest_brute
#define scene_eye_setup          rt_scene_eye_setup
#define scene_occluded           rt_scene_occluded
#define shape_init_box           rt_shape_init_box
#define shape_init_quadric       rt_shape_init_quadric
#define shape_init_torus         rt_shape_init_torus
#define shape_normal             rt_shape_normal
#define shape_set_world_bound    rt_shape_set_world_bound
#define shape_spans              rt_shape_spans
#define shape_world_box          rt_shape_world_box
#define shine_from_decimal       rt_shine_from_decimal
#define sky_colour               rt_sky_colour
#define solid_depth              rt_solid_depth
#define solid_max_spans          rt_solid_max_spans
#define spans_push               rt_spans_push
#define sphere_init              rt_sphere_init
#define sphere_normal            rt_sphere_normal
#define texture_colour           rt_texture_colour
#define texture_colour_at        rt_texture_colour_at
#define trace_ray                rt_trace_ray
#define xform_identity           rt_xform_identity
#define xform_mat_vec            rt_xform_mat_vec
#define xform_normal             rt_xform_normal
#define xform_point              rt_xform_point
#define xform_rotate             rt_xform_rotate
#define xform_scale              rt_xform_scale
#define xform_translate          rt_xform_translate

#endif
