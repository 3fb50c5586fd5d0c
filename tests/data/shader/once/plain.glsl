float plain_counter_decl;
