// SystemC's library calls sc_main from its own main(); gtest owns main here, so this stub only
// satisfies the linker.
extern "C" int sc_main(int, char**) {
  return 0;
}
