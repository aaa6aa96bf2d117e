# The files of the derivation page, check.html (names relative to web/): staged by the wasm build
# beside its module, copied by the docs into the site. Sets IMPULSELAB_CHECK_PAGE_FILES (copied as
# they are) and IMPULSELAB_CHECK_SITE_FILES (their names in the site, with the two the wasm build
# writes: the examples of the menu and the module).
set(IMPULSELAB_CHECK_PAGE_FILES
  check/check.html check/check.css check/check.js check/check_worker.js
  common/files.js common/page.css)
set(IMPULSELAB_CHECK_SITE_FILES)
foreach(file IN LISTS IMPULSELAB_CHECK_PAGE_FILES)
  get_filename_component(name "${file}" NAME)
  list(APPEND IMPULSELAB_CHECK_SITE_FILES "${name}")
endforeach()
list(APPEND IMPULSELAB_CHECK_SITE_FILES examples.js impulselab-check.js)
