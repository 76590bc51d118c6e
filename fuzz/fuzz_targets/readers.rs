#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| optri_fuzz::check_readers(data));
