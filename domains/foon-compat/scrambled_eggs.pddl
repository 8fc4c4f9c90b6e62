; foon2pddl, encoding foon-compat, level 3: 32 of 101 units after relevance pruning
; goal: scrambled eggs (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain universal_foon-626ff753)
  (:requirements :strips :typing)
  (:types
    object_node - object
  )
  (:constants
    avocado_halved_on_cutting_board - object_node
    avocado_in_bowl_mashed - object_node
    avocado_in_bowl_scooped - object_node
    avocado_on_cutting_board_whole - object_node
    avocado_whole - object_node
    black_pepper_ground - object_node
    black_pepper_in_bowl - object_node
    bowl_contains_avocado - object_node
    bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato - object_node
    bowl_contains_avocado_cilantro_lime_juice_onion_tomato - object_node
    bowl_contains_avocado_lime_juice - object_node
    bowl_contains_avocado_lime_juice_onion - object_node
    bowl_contains_avocado_lime_juice_onion_tomato - object_node
    bowl_contains_black_pepper_egg_milk_salt - object_node
    bowl_contains_egg - object_node
    bowl_contains_egg_milk - object_node
    bowl_contains_egg_mixture - object_node
    bowl_empty - object_node
    butter_in_frying_pan_melted - object_node
    butter_in_frying_pan_solid - object_node
    butter_solid - object_node
    cilantro_chopped_in_bowl - object_node
    cilantro_chopped_on_cutting_board - object_node
    cilantro_fresh - object_node
    cilantro_fresh_on_cutting_board - object_node
    cutting_board_contains_avocado - object_node
    cutting_board_contains_cilantro - object_node
    cutting_board_contains_lime - object_node
    cutting_board_contains_onion - object_node
    cutting_board_contains_tomato - object_node
    cutting_board_empty - object_node
    egg_beaten_in_bowl - object_node
    egg_cracked_in_bowl - object_node
    egg_whole - object_node
    egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl - object_node
    egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan - object_node
    fork - object_node
    frying_pan_contains_butter_on_stove - object_node
    frying_pan_contains_butter_egg_mixture_on_stove - object_node
    frying_pan_contains_scrambled_eggs_on_stove - object_node
    frying_pan_empty - object_node
    frying_pan_empty_on_stove - object_node
    juicer_contains_lime_juice - object_node
    juicer_empty - object_node
    knife - object_node
    lime_halved_on_cutting_board - object_node
    lime_on_cutting_board_whole - object_node
    lime_squeezed - object_node
    lime_whole - object_node
    lime_juice_in_bowl - object_node
    lime_juice_in_juicer - object_node
    milk_in_bowl - object_node
    milk_in_carton - object_node
    onion_chopped_in_bowl - object_node
    onion_chopped_on_cutting_board - object_node
    onion_on_cutting_board_peeled - object_node
    onion_on_cutting_board_whole - object_node
    onion_whole - object_node
    plate_contains_scrambled_eggs - object_node
    plate_empty - object_node
    salt_granulated - object_node
    salt_in_bowl - object_node
    scrambled_eggs_cooked_in_frying_pan - object_node
    scrambled_eggs_cooked_on_plate - object_node
    spatula - object_node
    spoon - object_node
    stove_off - object_node
    stove_on - object_node
    tomato_chopped_in_bowl - object_node
    tomato_chopped_on_cutting_board - object_node
    tomato_on_cutting_board_whole - object_node
    tomato_whole - object_node
    whisk - object_node
  )
  (:predicates
    (is_available ?obj - object_node)  ; the object node is available
  )

  (:action functional_unit_17
    ; unit 17: crack from 03-scrambled_eggs.foon:3, 05-french_toast.foon:3
    ; crack: bowl (empty), egg (whole) -> bowl (contains {egg}), egg (cracked, in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_empty)
      (is_available egg_whole)
    )
    :effect (and
      (is_available bowl_contains_egg)
      (is_available egg_cracked_in_bowl)
    )
  )

  (:action functional_unit_18
    ; unit 18: beat from 03-scrambled_eggs.foon:14
    ; beat: egg (cracked, in [bowl]), whisk -> egg (beaten, in [bowl]), whisk
    :parameters ()
    :precondition (and
      (is_available egg_cracked_in_bowl)
      (is_available whisk)
    )
    :effect (and
      (is_available egg_beaten_in_bowl)
      (is_available whisk)
    )
  )

  (:action functional_unit_19
    ; unit 19: pour from 03-scrambled_eggs.foon:24, 05-french_toast.foon:24
    ; pour: bowl (contains {egg}), egg (beaten, in [bowl]), milk (in [carton]) -> bowl (contains {egg, milk}), milk (in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_egg)
      (is_available egg_beaten_in_bowl)
      (is_available milk_in_carton)
    )
    :effect (and
      (is_available bowl_contains_egg_milk)
      (is_available milk_in_bowl)
    )
  )

  (:action functional_unit_20
    ; unit 20: sprinkle from 03-scrambled_eggs.foon:37
    ; sprinkle: bowl (contains {egg, milk}), salt (granulated), black pepper (ground) -> bowl (contains {black pepper, egg, milk, salt}), salt (in [bowl]), black pepper (in [bowl])
    :parameters ()
    :precondition (and
      (is_available black_pepper_ground)
      (is_available bowl_contains_egg_milk)
      (is_available salt_granulated)
    )
    :effect (and
      (is_available black_pepper_in_bowl)
      (is_available bowl_contains_black_pepper_egg_milk_salt)
      (is_available salt_in_bowl)
    )
  )

  (:action functional_unit_21
    ; unit 21: mix from 03-scrambled_eggs.foon:51
    ; mix: bowl (contains {black pepper, egg, milk, salt}), egg (beaten, in [bowl]), milk (in [bowl]), salt (in [bowl]), black pepper (in [bowl]), whisk -> bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, i...
    :parameters ()
    :precondition (and
      (is_available black_pepper_in_bowl)
      (is_available bowl_contains_black_pepper_egg_milk_salt)
      (is_available egg_beaten_in_bowl)
      (is_available milk_in_bowl)
      (is_available salt_in_bowl)
      (is_available whisk)
    )
    :effect (and
      (is_available bowl_contains_egg_mixture)
      (is_available egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl)
      (is_available whisk)
    )
  )

  (:action functional_unit_22
    ; unit 22: pick-and-place from 03-scrambled_eggs.foon:71, 04-pancakes.foon:76, 05-french_toast.foon:83
    ; pick-and-place: frying pan (empty), stove (off) -> frying pan (empty, on [stove])
    :parameters ()
    :precondition (and
      (is_available frying_pan_empty)
      (is_available stove_off)
    )
    :effect (and
      (is_available frying_pan_empty_on_stove)
    )
  )

  (:action functional_unit_23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters ()
    :precondition (and
      (is_available stove_off)
    )
    :effect (and
      (is_available stove_on)
    )
  )

  (:action functional_unit_24
    ; unit 24: pick-and-place from 03-scrambled_eggs.foon:86, 04-pancakes.foon:91, 05-french_toast.foon:98
    ; pick-and-place: frying pan (empty, on [stove]), butter (solid) -> frying pan (contains {butter}, on [stove]), butter (in [frying pan], solid)
    :parameters ()
    :precondition (and
      (is_available butter_solid)
      (is_available frying_pan_empty_on_stove)
    )
    :effect (and
      (is_available butter_in_frying_pan_solid)
      (is_available frying_pan_contains_butter_on_stove)
    )
  )

  (:action functional_unit_25
    ; unit 25: melt from 03-scrambled_eggs.foon:99, 04-pancakes.foon:104, 05-french_toast.foon:111
    ; melt: stove (on), butter (in [frying pan], solid) -> butter (in [frying pan], melted)
    :parameters ()
    :precondition (and
      (is_available butter_in_frying_pan_solid)
      (is_available stove_on)
    )
    :effect (and
      (is_available butter_in_frying_pan_melted)
    )
  )

  (:action functional_unit_26
    ; unit 26: pour from 03-scrambled_eggs.foon:109
    ; pour: bowl (contains {egg mixture}), egg mixture (contains {black pepper, egg, milk, salt}, in [bowl]), frying pan (contains {butter}, on [stove]), butter (in [frying pan], melted) -> frying pan (contains {butter, egg mixture}, on [stove...
    :parameters ()
    :precondition (and
      (is_available bowl_contains_egg_mixture)
      (is_available butter_in_frying_pan_melted)
      (is_available egg_mixture_contains_black_pepper_egg_milk_salt_in_bowl)
      (is_available frying_pan_contains_butter_on_stove)
    )
    :effect (and
      (is_available egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan)
      (is_available frying_pan_contains_butter_egg_mixture_on_stove)
    )
  )

  (:action functional_unit_27
    ; unit 27: stir from 03-scrambled_eggs.foon:128
    ; stir: stove (on), frying pan (contains {butter, egg mixture}, on [stove]), egg mixture (contains {black pepper, egg, milk, salt}, in [frying pan]), spatula -> frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in...
    :parameters ()
    :precondition (and
      (is_available egg_mixture_contains_black_pepper_egg_milk_salt_in_frying_pan)
      (is_available frying_pan_contains_butter_egg_mixture_on_stove)
      (is_available spatula)
      (is_available stove_on)
    )
    :effect (and
      (is_available frying_pan_contains_scrambled_eggs_on_stove)
      (is_available scrambled_eggs_cooked_in_frying_pan)
      (is_available spatula)
    )
  )

  (:action functional_unit_28
    ; unit 28: scoop from 03-scrambled_eggs.foon:146
    ; scoop: frying pan (contains {scrambled eggs}, on [stove]), scrambled eggs (cooked, in [frying pan]), spatula, plate (empty) -> plate (contains {scrambled eggs}), scrambled eggs (cooked, on [plate]), spatula
    :parameters ()
    :precondition (and
      (is_available frying_pan_contains_scrambled_eggs_on_stove)
      (is_available plate_empty)
      (is_available scrambled_eggs_cooked_in_frying_pan)
      (is_available spatula)
    )
    :effect (and
      (is_available plate_contains_scrambled_eggs)
      (is_available scrambled_eggs_cooked_on_plate)
      (is_available spatula)
    )
  )

  (:action functional_unit_39
    ; unit 39: beat from 05-french_toast.foon:14
    ; beat: egg (cracked, in [bowl]), fork -> egg (beaten, in [bowl]), fork
    :parameters ()
    :precondition (and
      (is_available egg_cracked_in_bowl)
      (is_available fork)
    )
    :effect (and
      (is_available egg_beaten_in_bowl)
      (is_available fork)
    )
  )

  (:action functional_unit_47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (is_available cutting_board_empty)
      (is_available onion_whole)
    )
    :effect (and
      (is_available cutting_board_contains_onion)
      (is_available onion_on_cutting_board_whole)
    )
  )

  (:action functional_unit_48
    ; unit 48: peel from 06-tomato_soup.foon:14, 07-guacamole.foon:116, 08-greek_salad.foon:64
    ; peel: cutting board (contains {onion}), onion (on [cutting board], whole), knife -> cutting board (contains {onion}), onion (on [cutting board], peeled), knife
    :parameters ()
    :precondition (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_on_cutting_board_whole)
    )
    :effect (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_on_cutting_board_peeled)
    )
  )

  (:action functional_unit_49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_on_cutting_board_peeled)
    )
    :effect (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_chopped_on_cutting_board)
    )
  )

  (:action functional_unit_50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (is_available cutting_board_empty)
      (is_available tomato_whole)
    )
    :effect (and
      (is_available cutting_board_contains_tomato)
      (is_available tomato_on_cutting_board_whole)
    )
  )

  (:action functional_unit_51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (is_available cutting_board_contains_tomato)
      (is_available knife)
      (is_available tomato_on_cutting_board_whole)
    )
    :effect (and
      (is_available cutting_board_contains_tomato)
      (is_available knife)
      (is_available tomato_chopped_on_cutting_board)
    )
  )

  (:action functional_unit_63
    ; unit 63: pick-and-place from 07-guacamole.foon:3
    ; pick-and-place: cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (is_available avocado_whole)
      (is_available cutting_board_empty)
    )
    :effect (and
      (is_available avocado_on_cutting_board_whole)
      (is_available cutting_board_contains_avocado)
    )
  )

  (:action functional_unit_64
    ; unit 64: cut from 07-guacamole.foon:14
    ; cut: cutting board (contains {avocado}), avocado (on [cutting board], whole), knife -> cutting board (contains {avocado}), avocado (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (is_available avocado_on_cutting_board_whole)
      (is_available cutting_board_contains_avocado)
      (is_available knife)
    )
    :effect (and
      (is_available avocado_halved_on_cutting_board)
      (is_available cutting_board_contains_avocado)
      (is_available knife)
    )
  )

  (:action functional_unit_65
    ; unit 65: scoop from 07-guacamole.foon:28
    ; scoop: avocado (halved, on [cutting board]), spoon, bowl (empty) -> bowl (contains {avocado}), avocado (in [bowl], scooped), spoon
    :parameters ()
    :precondition (and
      (is_available avocado_halved_on_cutting_board)
      (is_available bowl_empty)
      (is_available spoon)
    )
    :effect (and
      (is_available avocado_in_bowl_scooped)
      (is_available bowl_contains_avocado)
      (is_available spoon)
    )
  )

  (:action functional_unit_66
    ; unit 66: mash from 07-guacamole.foon:42
    ; mash: avocado (in [bowl], scooped), fork -> avocado (in [bowl], mashed), fork
    :parameters ()
    :precondition (and
      (is_available avocado_in_bowl_scooped)
      (is_available fork)
    )
    :effect (and
      (is_available avocado_in_bowl_mashed)
      (is_available fork)
    )
  )

  (:action functional_unit_67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (is_available cutting_board_empty)
      (is_available lime_whole)
    )
    :effect (and
      (is_available cutting_board_contains_lime)
      (is_available lime_on_cutting_board_whole)
    )
  )

  (:action functional_unit_68
    ; unit 68: cut from 07-guacamole.foon:63, 09-fruit_salad.foon:94
    ; cut: cutting board (contains {lime}), lime (on [cutting board], whole), knife -> cutting board (contains {lime}), lime (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (is_available cutting_board_contains_lime)
      (is_available knife)
      (is_available lime_on_cutting_board_whole)
    )
    :effect (and
      (is_available cutting_board_contains_lime)
      (is_available knife)
      (is_available lime_halved_on_cutting_board)
    )
  )

  (:action functional_unit_69
    ; unit 69: squeeze from 07-guacamole.foon:77, 09-fruit_salad.foon:108
    ; squeeze: lime (halved, on [cutting board]), juicer (empty) -> lime (squeezed), juicer (contains {lime juice}), lime juice (in [juicer])
    :parameters ()
    :precondition (and
      (is_available juicer_empty)
      (is_available lime_halved_on_cutting_board)
    )
    :effect (and
      (is_available juicer_contains_lime_juice)
      (is_available lime_squeezed)
      (is_available lime_juice_in_juicer)
    )
  )

  (:action functional_unit_70
    ; unit 70: pour from 07-guacamole.foon:90
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {avocado}), avocado (in [bowl], mashed) -> bowl (contains {avocado, lime juice}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (is_available avocado_in_bowl_mashed)
      (is_available bowl_contains_avocado)
      (is_available juicer_contains_lime_juice)
      (is_available lime_juice_in_juicer)
    )
    :effect (and
      (is_available bowl_contains_avocado_lime_juice)
      (is_available lime_juice_in_bowl)
    )
  )

  (:action functional_unit_71
    ; unit 71: pick-and-place from 07-guacamole.foon:144
    ; pick-and-place: bowl (contains {avocado, lime juice}), onion (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion}), onion (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_avocado_lime_juice)
      (is_available onion_chopped_on_cutting_board)
    )
    :effect (and
      (is_available bowl_contains_avocado_lime_juice_onion)
      (is_available onion_chopped_in_bowl)
    )
  )

  (:action functional_unit_72
    ; unit 72: pick-and-place from 07-guacamole.foon:181
    ; pick-and-place: bowl (contains {avocado, lime juice, onion}), tomato (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_avocado_lime_juice_onion)
      (is_available tomato_chopped_on_cutting_board)
    )
    :effect (and
      (is_available bowl_contains_avocado_lime_juice_onion_tomato)
      (is_available tomato_chopped_in_bowl)
    )
  )

  (:action functional_unit_73
    ; unit 73: pick-and-place from 07-guacamole.foon:193
    ; pick-and-place: cutting board (empty), cilantro (fresh) -> cutting board (contains {cilantro}), cilantro (fresh, on [cutting board])
    :parameters ()
    :precondition (and
      (is_available cilantro_fresh)
      (is_available cutting_board_empty)
    )
    :effect (and
      (is_available cilantro_fresh_on_cutting_board)
      (is_available cutting_board_contains_cilantro)
    )
  )

  (:action functional_unit_74
    ; unit 74: chop from 07-guacamole.foon:204
    ; chop: cutting board (contains {cilantro}), cilantro (fresh, on [cutting board]), knife -> cutting board (contains {cilantro}), cilantro (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (is_available cilantro_fresh_on_cutting_board)
      (is_available cutting_board_contains_cilantro)
      (is_available knife)
    )
    :effect (and
      (is_available cilantro_chopped_on_cutting_board)
      (is_available cutting_board_contains_cilantro)
      (is_available knife)
    )
  )

  (:action functional_unit_75
    ; unit 75: pick-and-place from 07-guacamole.foon:218
    ; pick-and-place: bowl (contains {avocado, lime juice, onion, tomato}), cilantro (chopped, on [cutting board]) -> bowl (contains {avocado, cilantro, lime juice, onion, tomato}), cilantro (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_avocado_lime_juice_onion_tomato)
      (is_available cilantro_chopped_on_cutting_board)
    )
    :effect (and
      (is_available bowl_contains_avocado_cilantro_lime_juice_onion_tomato)
      (is_available cilantro_chopped_in_bowl)
    )
  )

  (:action functional_unit_76
    ; unit 76: sprinkle from 07-guacamole.foon:230
    ; sprinkle: bowl (contains {avocado, cilantro, lime juice, onion, tomato}), salt (granulated) -> bowl (contains {avocado, cilantro, lime juice, onion, salt, tomato}), salt (in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_avocado_cilantro_lime_juice_onion_tomato)
      (is_available salt_granulated)
    )
    :effect (and
      (is_available bowl_contains_avocado_cilantro_lime_juice_onion_salt_tomato)
      (is_available salt_in_bowl)
    )
  )
)
