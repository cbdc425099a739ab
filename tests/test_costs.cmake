# Measured cost of the slow tests (seconds on the 2-core CI machine's class, from CTest's own cost data of
# a whole run), for CTest's scheduling: in a fresh build there is no cost history, so `ctest -j2` would
# start tests in the order they were defined and a slow one defined late would run alone at the end,
# leaving a core idle. With COST set, the slowest start first. The figures order the tests; they assert
# nothing. Tests under 15 s keep the default order.
set(ROLLSPEC_TEST_COSTS
  cli_test_every_study 505
  cli_test_coverage 329
  cli_test_fit_rig_coverage 296
  cli_test_seed001_chain 285
  post_test_post_faults 221
  docs 150
  cli_test_fit_impacts 132
  cli_test_fit_coverage 127
  cli_test_program_faults 100
  cli_test_table_jackknife_noise 97
  cli_test_solver_against_path 83
  cli_test_blocked_force_defaults 83
  cli_test_memory_estimate 78
  cli_test_readme_using_it 74
  test_contact 63
  test_equivalent_roughness_psd 50
  cli_test_tail_check 49
  cli_test_fit_joint 48
  post_test_report_rig 46
  cli_test_table_jackknife 42
  cli_test_output_faults 41
  cli_test_fit_table 40
  cli_test_measured_profiles 39
  cli_test_faults 37
  cli_test_data_safety_names 35
  test_contact_sides 34
  post_test_psd_plot 34
  cli_test_stress 34
  cli_test_ball_on_beam 34
  post_test_report_compare 33
  mpi_test_mpi_ensemble 32
  cli_test_random_studies 32
  install_find_package 31
  cli_test_solver_filter_defaults 31
  cli_test_bench_recording_verdict 30
  cli_test_stages 28
  install_python_post 27
  cli_test_fit 26
  post_test_sweep_point 25
  post_test_panels_plot 25
  cli_test_init_command 25
  cli_test_fit_warnings 24
  cli_test_unit_slips 23
  post_test_loss_of_contact_notes 21
  cli_test_new_user_path 21
  post_test_trajectory_plot 20
  post_test_sweep_plot 20
  post_test_report_page 20
  post_test_roughness_filter_plot 19
  post_test_bench_plot 19
  cli_test_sweep 18
  post_test_texture_plot 17
  cli_test_stiffness 17
  cli_test_solver_filter 17
  cli_test_table_jackknife_strips 16
  cli_test_table_jackknife_segments 16
  post_test_stiffness_plot 15
  cli_test_notebook_access 15
  cli_test_fit_whole 15
  cli_test_contact_filter 15
)

# The same under the sanitizers (preset asan-ubsan: its test pass, tests over 10 s, from a whole pass's cost data
# after the long simulations moved to NAME_long), where the order differs: the rolling kernels' and scenes' tests
# are slow there and quick in the release build.
set(ROLLSPEC_TEST_COSTS_SANITIZED
  test_rolling 50
  test_spectral 40
  cli_test_ball_on_beam 30
  test_contact 55
  cli_test_stress 35
  cli_test_stages 46
  cli_test_blocked_force 41
  cli_test_profile_surfaces 36
  cli_test_solver_filter 33
  cli_test_measured_profiles 33
  test_contact_sides 32
  cli_test_init_command 31
  cli_test_fit 31
  cli_test_sweep 30
  cli_test_compare_combined 28
  cli_test_data_safety 28
  cli_test_compare_recordings 27
  cli_test_path_law 26
  cli_test_rolling_pipe 25
  cli_test_table_jackknife_segments 24
  test_texture 23
  cli_test_loss_of_contact_flags 23
  cli_test_terminal 22
  cli_test_table_jackknife_strips 21
  cli_test_notebook_access 21
  cli_test_ensemble_reproducibility 21
  cli_test_contact_filter 20
  cli_test_rolling_beam 19
  cli_test_seed002_speed_trend 18
  cli_test_stiffness 16
  test_beam_dynamics 14
  cli_test_fit_whole 14
  cli_test_logger_import 13
  cli_test_measurement_files 13
  cli_test_compare 12
  cli_test_profiles_whole 12
  cli_test_logger_corpus 12
  cli_test_contact_bounce_growth 11
)
if(CMAKE_CXX_FLAGS MATCHES "-fsanitize=address")
  set(ROLLSPEC_TEST_COSTS ${ROLLSPEC_TEST_COSTS_SANITIZED})
endif()

# rollspec_test_cost(NAME): the test's COST from the list above, where it is listed.
function(rollspec_test_cost name)
  list(FIND ROLLSPEC_TEST_COSTS ${name} at)
  if(at GREATER_EQUAL 0)
    math(EXPR at "${at} + 1")
    list(GET ROLLSPEC_TEST_COSTS ${at} cost)
    set_tests_properties(${name} PROPERTIES COST ${cost})
    set_property(GLOBAL APPEND PROPERTY ROLLSPEC_COSTED ${name})
  endif()
endfunction()

# rollspec_check_test_costs(): a listed name that no test took (renamed or removed) is said at configure
# time, so the list does not go stale unseen. Tests a configuration leaves out (mpi_, the sanitizer
# build's) are not named.
function(rollspec_check_test_costs)
  get_property(costed GLOBAL PROPERTY ROLLSPEC_COSTED)
  set(i 0)
  list(LENGTH ROLLSPEC_TEST_COSTS n)
  while(i LESS n)
    list(GET ROLLSPEC_TEST_COSTS ${i} name)
    if(NOT name IN_LIST costed AND NOT (name MATCHES "^mpi_" AND NOT (ROLLSPEC_MPI OR ROLLSPEC_MPI_COMMAND)))
      message(AUTHOR_WARNING "tests/test_costs.cmake: no test named '${name}'")
    endif()
    math(EXPR i "${i} + 2")
  endwhile()
endfunction()
