# `cmake --install build --prefix PREFIX`: the executable in PREFIX/bin and what it reads at run
# time in PREFIX/share/valsalva, laid out as in the source tree (run/data_dir.hpp finds it
# relative to the executable): the validation cases' scenes, plot scripts and reference data,
# and the plot scripts of compare-piv and psd.
include(GNUInstallDirs)
install(TARGETS valsalva RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/validation/ DESTINATION ${CMAKE_INSTALL_DATADIR}/valsalva/validation
  FILES_MATCHING PATTERN "*.py" PATTERN "*.toml" PATTERN "*.csv" PATTERN "*.txt" PATTERN "*.dat"
  PATTERN "*.gdiag" PATTERN "*.es" PATTERN "*.f_t" PATTERN "*.md" PATTERN "*.json"
  PATTERN "bench" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/analysis/plot_piv.py ${PROJECT_SOURCE_DIR}/analysis/plot_psd.py
  ${PROJECT_SOURCE_DIR}/analysis/plot_valve.py ${PROJECT_SOURCE_DIR}/analysis/circulation_cycles.py
  DESTINATION ${CMAKE_INSTALL_DATADIR}/valsalva/analysis)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/valsalva/scenes
  FILES_MATCHING PATTERN "*.toml" PATTERN "*.csv")
