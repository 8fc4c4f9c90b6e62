; foon2pddl, encoding tree, level 3: 32 of 101 units after relevance pruning
; goal: scrambled eggs (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-tree-d0948af9)
  (:requirements :strips)
  (:predicates
    (avocado_halved_on_cutting_board)  ; avocado (halved, on [cutting board])
    (avocado_in_bowl_mashed)  ; avocado (in [bowl], mashed)
    (avocado_in_bowl_scooped)  ; avocado (in [bowl], scooped)
    (avocado_on_cutting_board_whole)  ; avocado (on [cutting board], whole)
    (avocado_whole)  ; avocado (whole)
    (black_pepper_ground)  ; black pepper (ground)
    (black_pepper_in_bowl)  ; black pepper (in [bowl])
    (bowl_contains_avocado)  ; bowl (contains {avocado})
    (bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)  ; bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato})
    (bowl_contains_avocado_cilantro_lime_juice_onion_tomato)  ; bowl (contains {avocado, cilantro, lime juice, onion, tomato})
    (bowl_contains_avocado_lime_juice)  ; bowl (contains {avocado, lime juice})
    (bowl_contains_avocado_lime_juice_onion)  ; bowl (contains {avocado, lime juice, onion})
    (bowl_contains_avocado_lime_juice_onion_tomato)  ; bowl (contains {avocado, lime juice, onion, tomato})
    (bowl_contains_black_pepper_egg_milk_salt)  ; bowl (contains {black pepper, egg, milk, salt})
    (bowl_contains_egg)  ; bowl (contains {egg})
    (bowl_contains_egg_milk)  ; bowl (contains {egg, milk})
    (bowl_contains_egg_mixture)  ; bowl (contains {egg mixture})
    (bowl_empty)  ; bowl (empty)
    (butter_in_frying_pan_melted)  ; butter (in [frying pan], melted)
    (butter_in_frying_pan_solid)  ; butter (in [frying pan], solid)
    (butter_solid)  ; butter (solid)
    (cilantro_chopped_in_bowl)  ; cilantro (chopped, in [bowl])
    (cilantro_chopped_on_cutting_board)  ; cilantro (chopped, on [cutting board])
    (cilantro_fresh)  ; cilantro (fresh)
    (cilantro_fresh_on_cutting_board)  ; cilantro (fresh, on [cutting board])
    (cutting_board_contains_avocado)  ; cutting board (contains {avocado})
    (cutting_board_contains_cilantro)  ; cutting board (contains {cilantro})
    (cutting_board_contains_lime)  ; cutting board (contains {lime})
    (cutting_board_contains_onion)  ; cutting board (contains {onion})
    (cutting_board_contains_tomato)  ; cutting board (contains {tomato})
    (cutting_board_empty)  ; cutting board (empty)
    (egg_beaten_in_bowl)  ; egg (beaten, in [bowl])
    (egg_cracked_in_bowl)  ; egg (cracked, in [bowl])
    (egg_whole)  ; egg (whole)
    (egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl)  ; egg mixture (contains {black pepper, egg, milk, salt}, in [bowl])
    (egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan)  ; egg mixture (contains {black pepper, egg, milk, salt}, in [frying pan])
    (fork)  ; fork
    (frying_pan_contains_butter_on_stove)  ; frying pan (contains {butter}, on [stove])
    (frying_pan_contains_butter_egg_mixture_on_stove)  ; frying pan (contains {butter, egg mixture}, on [stove])
    (frying_pan_contains_scrambled_eggs_on_stove)  ; frying pan (contains {scrambled eggs}, on [stove])
    (frying_pan_empty)  ; frying pan (empty)
    (frying_pan_empty_on_stove)  ; frying pan (empty, on [stove])
    (juicer_contains_lime_juice)  ; juicer (contains {lime juice})
    (juicer_empty)  ; juicer (empty)
    (knife)  ; knife
    (lime_halved_on_cutting_board)  ; lime (halved, on [cutting board])
    (lime_on_cutting_board_whole)  ; lime (on [cutting board], whole)
    (lime_squeezed)  ; lime (squeezed)
    (lime_whole)  ; lime (whole)
    (lime_juice_in_bowl)  ; lime juice (in [bowl])
    (lime_juice_in_juicer)  ; lime juice (in [juicer])
    (milk_in_bowl)  ; milk (in [bowl])
    (milk_in_carton)  ; milk (in [carton])
    (onion_chopped_in_bowl)  ; onion (chopped, in [bowl])
    (onion_chopped_on_cutting_board)  ; onion (chopped, on [cutting board])
    (onion_on_cutting_board_peeled)  ; onion (on [cutting board], peeled)
    (onion_on_cutting_board_whole)  ; onion (on [cutting board], whole)
    (onion_whole)  ; onion (whole)
    (plate_contains_scrambled_eggs)  ; plate (contains {scrambled eggs})
    (plate_empty)  ; plate (empty)
    (salt_granulated)  ; salt (granulated)
    (salt_in_bowl)  ; salt (in [bowl])
    (scrambled_eggs_cooked_in_frying_pan)  ; scrambled eggs (cooked, in [frying pan])
    (scrambled_eggs_cooked_on_plate)  ; scrambled eggs (cooked, on [plate])
    (spatula)  ; spatula
    (spoon)  ; spoon
    (stove_off)  ; stove (off)
    (stove_on)  ; stove (on)
    (tomato_chopped_in_bowl)  ; tomato (chopped, in [bowl])
    (tomato_chopped_on_cutting_board)  ; tomato (chopped, on [cutting board])
    (tomato_on_cutting_board_whole)  ; tomato (on [cutting board], whole)
    (tomato_whole)  ; tomato (whole)
    (whisk)  ; whisk
  )

  (:action crack_u17
    ; unit 17: crack from 03-scrambled_eggs.foon:3, 05-french_toast.foon:3
    ; crack: bowl (empty), egg (whole) -> bowl (contains {egg}), egg (cracked, in [bowl])
    :parameters ()
    :precondition (and
      (bowl_empty)
      (egg_whole)
    )
    :effect (and
      (bowl_contains_egg)
      (egg_cracked_in_bowl)
    )
  )

  (:action beat_u18
    ; unit 18: beat from 03-scrambled_eggs.foon:14
    ; beat: egg (cracked, in [bowl]), whisk -> egg (beaten, in [bowl]), whisk
    :parameters ()
    :precondition (and
      (egg_cracked_in_bowl)
      (whisk)
    )
    :effect (and
      (egg_beaten_in_bowl)
      (whisk)
    )
  )

  (:action pour_u19
    ; unit 19: pour from 03-scrambled_eggs.foon:24, 05-french_toast.foon:24
    ; pour: bowl (contains {egg}), egg (beaten, in [bowl]), milk (in [carton]) -> bowl (contains {egg, milk}), milk (in [bowl])
    :parameters ()
    :precondition (and
      (bowl_contains_egg)
      (egg_beaten_in_bowl)
      (milk_in_carton)
    )
    :effect (and
      (bowl_contains_egg_milk)
      (milk_in_bowl)
    )
  )

  (:action sprinkle_u20
    ; unit 20: sprinkle from 03-scrambled_eggs.foon:37
    ; sprinkle: bowl (contains {egg, milk}), salt (granulated), black pepper (ground) -> bowl (contains {black pepper, egg, milk, salt}), salt (in [bowl]), black pepper (in [bowl])
    :parameters ()
    :precondition (and
      (black_pepper_ground)
      (bowl_contains_egg_milk)
      (salt_granulated)
    )
    :effect (and
      (black_pepper_in_bowl)
      (bowl_contains_black_pepper_egg_milk_salt)
      (salt_in_bowl)
    )
  )

  (:action mix_u21
    ; unit 21: mix from 03-scrambled_eggs.foon:51
    ; mix: bowl (contains {black pepper, egg, milk, salt}), egg (beaten, in [bowl]), milk (in [bowl]), salt (in [bowl]), black pepper (in [bowl]), whisk -> bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, i...
    :parameters ()
    :precondition (and
      (black_pepper_in_bowl)
      (bowl_contains_black_pepper_egg_milk_salt)
      (egg_beaten_in_bowl)
      (milk_in_bowl)
      (salt_in_bowl)
      (whisk)
    )
    :effect (and
      (bowl_contains_egg_mixture)
      (egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl)
      (whisk)
    )
  )

  (:action pick-and-place_u22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters ()
    :precondition (and
      (frying_pan_empty)
      (stove_off)
    )
    :effect (and
      (frying_pan_empty_on_stove)
    )
  )

  (:action turn_on_u23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters ()
    :precondition (and
      (stove_off)
    )
    :effect (and
      (stove_on)
    )
  )

  (:action pick-and-place_u24
    ; unit 24: pick-and-place from 03-scrambled_eggs.foon:86, 04-pancakes.foon:91, 05-french_toast.foon:98
    ; pick-and-place: frying pan (empty, on [stove]), butter (solid) -> frying pan (contains {butter}, on [stove]), butter (in [frying pan], solid)
    :parameters ()
    :precondition (and
      (butter_solid)
      (frying_pan_empty_on_stove)
    )
    :effect (and
      (butter_in_frying_pan_solid)
      (frying_pan_contains_butter_on_stove)
    )
  )

  (:action melt_u25
    ; unit 25: melt from 03-scrambled_eggs.foon:99, 04-pancakes.foon:104, 05-french_toast.foon:111
    ; melt: stove (on), butter (in [frying pan], solid) -> butter (in [frying pan], melted)
    :parameters ()
    :precondition (and
      (butter_in_frying_pan_solid)
      (stove_on)
    )
    :effect (and
      (butter_in_frying_pan_melted)
    )
  )

  (:action pour_u26
    ; unit 26: pour from 03-scrambled_eggs.foon:109
    ; pour: bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, in [bowl]), frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted) -> frying pan (contains {butter, egg mixture}, on [stove...
    :parameters ()
    :precondition (and
      (bowl_contains_egg_mixture)
      (butter_in_frying_pan_melted)
      (egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl)
      (frying_pan_contains_butter_on_stove)
    )
    :effect (and
      (egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan)
      (frying_pan_contains_butter_egg_mixture_on_stove)
    )
  )

  (:action stir_u27
    ; unit 27: stir from 03-scrambled_eggs.foon:128
    ; stir: stove (on), frying pan (contains {butter, egg mixture}, on [stove]), egg mixture (contains {black pepper, egg, milk, salt}, in [frying pan]), spatula -> frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in...
    :parameters ()
    :precondition (and
      (egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan)
      (frying_pan_contains_butter_egg_mixture_on_stove)
      (spatula)
      (stove_on)
    )
    :effect (and
      (frying_pan_contains_scrambled_eggs_on_stove)
      (scrambled_eggs_cooked_in_frying_pan)
      (spatula)
    )
  )

  (:action scoop_u28
    ; unit 28: scoop from 03-scrambled_eggs.foon:146
    ; scoop: frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {scrambled eggs}), scrambled eggs (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (frying_pan_contains_scrambled_eggs_on_stove)
      (plate_empty)
      (scrambled_eggs_cooked_in_frying_pan)
      (spatula)
    )
    :effect (and
      (plate_contains_scrambled_eggs)
      (scrambled_eggs_cooked_on_plate)
      (spatula)
    )
  )

  (:action beat_u39
    ; unit 39: beat from 05-french_toast.foon:14
    ; beat: egg (cracked, in [bowl]), fork -> egg (beaten, in [bowl]), fork
    :parameters ()
    :precondition (and
      (egg_cracked_in_bowl)
      (fork)
    )
    :effect (and
      (egg_beaten_in_bowl)
      (fork)
    )
  )

  (:action pick-and-place_u47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (cutting_board_empty)
      (onion_whole)
    )
    :effect (and
      (cutting_board_contains_onion)
      (onion_on_cutting_board_whole)
    )
  )

  (:action peel_u48
    ; unit 48: peel from 06-tomato_soup.foon:14, 07-guacamole.foon:116, 08-greek_salad.foon:64
    ; peel: cutting board (contains {onion}), onion (on [cutting board], whole), knife -> cutting board (contains {onion}), onion (on [cutting board], peeled), knife
    :parameters ()
    :precondition (and
      (cutting_board_contains_onion)
      (knife)
      (onion_on_cutting_board_whole)
    )
    :effect (and
      (cutting_board_contains_onion)
      (knife)
      (onion_on_cutting_board_peeled)
    )
  )

  (:action chop_u49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (cutting_board_contains_onion)
      (knife)
      (onion_on_cutting_board_peeled)
    )
    :effect (and
      (cutting_board_contains_onion)
      (knife)
      (onion_chopped_on_cutting_board)
    )
  )

  (:action pick-and-place_u50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (cutting_board_empty)
      (tomato_whole)
    )
    :effect (and
      (cutting_board_contains_tomato)
      (tomato_on_cutting_board_whole)
    )
  )

  (:action chop_u51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (cutting_board_contains_tomato)
      (knife)
      (tomato_on_cutting_board_whole)
    )
    :effect (and
      (cutting_board_contains_tomato)
      (knife)
      (tomato_chopped_on_cutting_board)
    )
  )

  (:action pick-and-place_u63
    ; unit 63: pick-and-place from 07-guacamole.foon:3
    ; pick-and-place: cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (avocado_whole)
      (cutting_board_empty)
    )
    :effect (and
      (avocado_on_cutting_board_whole)
      (cutting_board_contains_avocado)
    )
  )

  (:action cut_u64
    ; unit 64: cut from 07-guacamole.foon:14
    ; cut: cutting board (contains {avocado}), avocado (on [cutting board], whole), knife -> cutting board (contains {avocado}), avocado (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (avocado_on_cutting_board_whole)
      (cutting_board_contains_avocado)
      (knife)
    )
    :effect (and
      (avocado_halved_on_cutting_board)
      (cutting_board_contains_avocado)
      (knife)
    )
  )

  (:action scoop_u65
    ; unit 65: scoop from 07-guacamole.foon:28
    ; scoop: avocado (halved, on [cutting board]), spoon, bowl (empty) -> bowl (contains {avocado}), avocado (in [bowl], scooped), spoon
    :parameters ()
    :precondition (and
      (avocado_halved_on_cutting_board)
      (bowl_empty)
      (spoon)
    )
    :effect (and
      (avocado_in_bowl_scooped)
      (bowl_contains_avocado)
      (spoon)
    )
  )

  (:action mash_u66
    ; unit 66: mash from 07-guacamole.foon:42
    ; mash: avocado (in [bowl], scooped), fork -> avocado (in [bowl], mashed), fork
    :parameters ()
    :precondition (and
      (avocado_in_bowl_scooped)
      (fork)
    )
    :effect (and
      (avocado_in_bowl_mashed)
      (fork)
    )
  )

  (:action pick-and-place_u67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (cutting_board_empty)
      (lime_whole)
    )
    :effect (and
      (cutting_board_contains_lime)
      (lime_on_cutting_board_whole)
    )
  )

  (:action cut_u68
    ; unit 68: cut from 07-guacamole.foon:63, 09-fruit_salad.foon:94
    ; cut: cutting board (contains {lime}), lime (on [cutting board], whole), knife -> cutting board (contains {lime}), lime (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (cutting_board_contains_lime)
      (knife)
      (lime_on_cutting_board_whole)
    )
    :effect (and
      (cutting_board_contains_lime)
      (knife)
      (lime_halved_on_cutting_board)
    )
  )

  (:action squeeze_u69
    ; unit 69: squeeze from 07-guacamole.foon:77, 09-fruit_salad.foon:108
    ; squeeze: lime (halved, on [cutting board]), juicer (empty) -> lime (squeezed), juicer (contains {lime juice}), lime juice (in [juicer])
    :parameters ()
    :precondition (and
      (juicer_empty)
      (lime_halved_on_cutting_board)
    )
    :effect (and
      (juicer_contains_lime_juice)
      (lime_squeezed)
      (lime_juice_in_juicer)
    )
  )

  (:action pour_u70
    ; unit 70: pour from 07-guacamole.foon:90
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {avocado}), avocado (in [bowl], mashed) -> bowl (contains {avocado, lime juice}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (avocado_in_bowl_mashed)
      (bowl_contains_avocado)
      (juicer_contains_lime_juice)
      (lime_juice_in_juicer)
    )
    :effect (and
      (bowl_contains_avocado_lime_juice)
      (lime_juice_in_bowl)
    )
  )

  (:action pick-and-place_u71
    ; unit 71: pick-and-place from 07-guacamole.foon:144
    ; pick-and-place: bowl (contains {avocado, lime juice}), onion (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion}), onion (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (bowl_contains_avocado_lime_juice)
      (onion_chopped_on_cutting_board)
    )
    :effect (and
      (bowl_contains_avocado_lime_juice_onion)
      (onion_chopped_in_bowl)
    )
  )

  (:action pick-and-place_u72
    ; unit 72: pick-and-place from 07-guacamole.foon:181
    ; pick-and-place: bowl (contains {avocado, lime juice, onion}), tomato (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (bowl_contains_avocado_lime_juice_onion)
      (tomato_chopped_on_cutting_board)
    )
    :effect (and
      (bowl_contains_avocado_lime_juice_onion_tomato)
      (tomato_chopped_in_bowl)
    )
  )

  (:action pick-and-place_u73
    ; unit 73: pick-and-place from 07-guacamole.foon:193
    ; pick-and-place: cutting board (empty), cilantro (fresh) -> cutting board (contains {cilantro}), cilantro (fresh, on [cutting board])
    :parameters ()
    :precondition (and
      (cilantro_fresh)
      (cutting_board_empty)
    )
    :effect (and
      (cilantro_fresh_on_cutting_board)
      (cutting_board_contains_cilantro)
    )
  )

  (:action chop_u74
    ; unit 74: chop from 07-guacamole.foon:204
    ; chop: cutting board (contains {cilantro}), cilantro (fresh, on [cutting board]), knife -> cutting board (contains {cilantro}), cilantro (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (cilantro_fresh_on_cutting_board)
      (cutting_board_contains_cilantro)
      (knife)
    )
    :effect (and
      (cilantro_chopped_on_cutting_board)
      (cutting_board_contains_cilantro)
      (knife)
    )
  )

  (:action pick-and-place_u75
    ; unit 75: pick-and-place from 07-guacamole.foon:218
    ; pick-and-place: bowl (contains {avocado, lime juice, onion, tomato}), cilantro (chopped, on [cutting board]) -> bowl (contains {avocado, cilantro, lime juice, onion, tomato}), cilantro (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (bowl_contains_avocado_lime_juice_onion_tomato)
      (cilantro_chopped_on_cutting_board)
    )
    :effect (and
      (bowl_contains_avocado_cilantro_lime_juice_onion_tomato)
      (cilantro_chopped_in_bowl)
    )
  )

  (:action sprinkle_u76
    ; unit 76: sprinkle from 07-guacamole.foon:230
    ; sprinkle: bowl (contains {avocado, cilantro, lime juice, onion, tomato}), salt (granulated) -> bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), salt (in [bowl])
    :parameters ()
    :precondition (and
      (bowl_contains_avocado_cilantro_lime_juice_onion_tomato)
      (salt_granulated)
    )
    :effect (and
      (bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)
      (salt_in_bowl)
    )
  )
)
