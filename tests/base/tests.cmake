# base/: names made safe to print. Unit tier.
speculum_add_test(BaseTest TIER unit SOURCES PrintableTest.cpp LIBS speculum_base)
