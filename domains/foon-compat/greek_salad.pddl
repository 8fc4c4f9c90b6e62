; foon2pddl, encoding foon-compat, level 3: 26 of 101 units after relevance pruning
; goal: greek salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain universal_foon-c9a7e925)
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
    black_olive_in_bowl_pitted - object_node
    black_olive_pitted - object_node
    bowl_contains_avocado - object_node
    bowl_contains_avocado_lime_juice - object_node
    bowl_contains_avocado_lime_juice_onion - object_node
    bowl_contains_avocado_lime_juice_onion_tomato - object_node
    bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6 - object_node
    bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4 - object_node
    bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato - object_node
    bowl_contains_black_olive_cucumber_onion_tomato - object_node
    bowl_contains_cucumber - object_node
    bowl_contains_cucumber_onion_tomato - object_node
    bowl_contains_cucumber_tomato - object_node
    bowl_contains_greek_salad - object_node
    bowl_empty - object_node
    cucumber_in_bowl_sliced - object_node
    cucumber_on_cutting_board_sliced - object_node
    cucumber_on_cutting_board_whole - object_node
    cucumber_whole - object_node
    cutting_board_contains_avocado - object_node
    cutting_board_contains_cucumber - object_node
    cutting_board_contains_lime - object_node
    cutting_board_contains_onion - object_node
    cutting_board_contains_tomato - object_node
    cutting_board_empty - object_node
    feta_cheese_crumbled - object_node
    feta_cheese_crumbled_in_bowl - object_node
    fork - object_node
    greek_salad_contains_black_olive_cucumber_feta_cheese_olive_oil_onion__afe10915 - object_node
    juicer_contains_lime_juice - object_node
    juicer_empty - object_node
    knife - object_node
    lime_halved_on_cutting_board - object_node
    lime_on_cutting_board_whole - object_node
    lime_squeezed - object_node
    lime_whole - object_node
    lime_juice_in_bowl - object_node
    lime_juice_in_juicer - object_node
    olive_oil_in_bottle - object_node
    olive_oil_in_bowl - object_node
    onion_chopped_in_bowl - object_node
    onion_chopped_on_cutting_board - object_node
    onion_in_bowl_sliced - object_node
    onion_on_cutting_board_peeled - object_node
    onion_on_cutting_board_sliced - object_node
    onion_on_cutting_board_whole - object_node
    onion_whole - object_node
    oregano_dried - object_node
    oregano_in_bowl - object_node
    red_wine_vinegar_in_bottle - object_node
    red_wine_vinegar_in_bowl - object_node
    salad_tongs - object_node
    spoon - object_node
    tomato_chopped_in_bowl - object_node
    tomato_chopped_on_cutting_board - object_node
    tomato_on_cutting_board_whole - object_node
    tomato_whole - object_node
  )
  (:predicates
    (is_available ?obj - object_node)  ; the object node is available
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

  (:action functional_unit_78
    ; unit 78: pick-and-place from 08-greek_salad.foon:3
    ; pick-and-place: cutting board (empty), cucumber (whole) -> cutting board (contains {cucumber}), cucumber (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (is_available cucumber_whole)
      (is_available cutting_board_empty)
    )
    :effect (and
      (is_available cucumber_on_cutting_board_whole)
      (is_available cutting_board_contains_cucumber)
    )
  )

  (:action functional_unit_79
    ; unit 79: slice from 08-greek_salad.foon:14
    ; slice: cutting board (contains {cucumber}), cucumber (on [cutting board], whole), knife -> cutting board (contains {cucumber}), cucumber (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (is_available cucumber_on_cutting_board_whole)
      (is_available cutting_board_contains_cucumber)
      (is_available knife)
    )
    :effect (and
      (is_available cucumber_on_cutting_board_sliced)
      (is_available cutting_board_contains_cucumber)
      (is_available knife)
    )
  )

  (:action functional_unit_80
    ; unit 80: slice from 08-greek_salad.foon:78
    ; slice: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_on_cutting_board_peeled)
    )
    :effect (and
      (is_available cutting_board_contains_onion)
      (is_available knife)
      (is_available onion_on_cutting_board_sliced)
    )
  )

  (:action functional_unit_81
    ; unit 81: pick-and-place from 08-greek_salad.foon:92
    ; pick-and-place: bowl (empty), cucumber (on [cutting board], sliced) -> bowl (contains {cucumber}), cucumber (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (is_available bowl_empty)
      (is_available cucumber_on_cutting_board_sliced)
    )
    :effect (and
      (is_available bowl_contains_cucumber)
      (is_available cucumber_in_bowl_sliced)
    )
  )

  (:action functional_unit_82
    ; unit 82: pick-and-place from 08-greek_salad.foon:104
    ; pick-and-place: bowl (contains {cucumber}), tomato (chopped, on [cutting board]) -> bowl (contains {cucumber, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_cucumber)
      (is_available tomato_chopped_on_cutting_board)
    )
    :effect (and
      (is_available bowl_contains_cucumber_tomato)
      (is_available tomato_chopped_in_bowl)
    )
  )

  (:action functional_unit_83
    ; unit 83: pick-and-place from 08-greek_salad.foon:116
    ; pick-and-place: bowl (contains {cucumber, tomato}), onion (on [cutting board], sliced) -> bowl (contains {cucumber, onion, tomato}), onion (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (is_available bowl_contains_cucumber_tomato)
      (is_available onion_on_cutting_board_sliced)
    )
    :effect (and
      (is_available bowl_contains_cucumber_onion_tomato)
      (is_available onion_in_bowl_sliced)
    )
  )

  (:action functional_unit_84
    ; unit 84: pick-and-place from 08-greek_salad.foon:128
    ; pick-and-place: bowl (contains {cucumber, onion, tomato}), black olive (pitted) -> bowl (contains {black olive, cucumber, onion, tomato}), black olive (in [bowl], pitted)
    :parameters ()
    :precondition (and
      (is_available black_olive_pitted)
      (is_available bowl_contains_cucumber_onion_tomato)
    )
    :effect (and
      (is_available black_olive_in_bowl_pitted)
      (is_available bowl_contains_black_olive_cucumber_onion_tomato)
    )
  )

  (:action functional_unit_85
    ; unit 85: sprinkle from 08-greek_salad.foon:139
    ; sprinkle: bowl (contains {black olive, cucumber, onion, tomato}), feta cheese (crumbled) -> bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), feta cheese (crumbled, in [bowl])
    :parameters ()
    :precondition (and
      (is_available bowl_contains_black_olive_cucumber_onion_tomato)
      (is_available feta_cheese_crumbled)
    )
    :effect (and
      (is_available bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato)
      (is_available feta_cheese_crumbled_in_bowl)
    )
  )

  (:action functional_unit_86
    ; unit 86: pour* from 08-greek_salad.foon:150
    ; pour: bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), olive oil (in [bottle]), red wine vinegar (in [bottle]) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), olive...
    :parameters ()
    :precondition (and
      (is_available bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato)
      (is_available olive_oil_in_bottle)
      (is_available red_wine_vinegar_in_bottle)
    )
    :effect (and
      (is_available bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4)
      (is_available olive_oil_in_bowl)
      (is_available red_wine_vinegar_in_bowl)
    )
  )

  (:action functional_unit_87
    ; unit 87: sprinkle from 08-greek_salad.foon:164
    ; sprinkle: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), oregano (dried) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), ore...
    :parameters ()
    :precondition (and
      (is_available bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4)
      (is_available oregano_dried)
    )
    :effect (and
      (is_available bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6)
      (is_available oregano_in_bowl)
    )
  )

  (:action functional_unit_88
    ; unit 88: toss from 08-greek_salad.foon:174
    ; toss: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), cucumber (in [bowl], sliced), tomato (chopped, in [bowl]), onion (in [bowl], sliced), black olive (in [bowl], pitted), feta ...
    :parameters ()
    :precondition (and
      (is_available black_olive_in_bowl_pitted)
      (is_available bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6)
      (is_available cucumber_in_bowl_sliced)
      (is_available feta_cheese_crumbled_in_bowl)
      (is_available olive_oil_in_bowl)
      (is_available onion_in_bowl_sliced)
      (is_available oregano_in_bowl)
      (is_available red_wine_vinegar_in_bowl)
      (is_available salad_tongs)
      (is_available tomato_chopped_in_bowl)
    )
    :effect (and
      (is_available bowl_contains_greek_salad)
      (is_available greek_salad_contains_black_olive_cucumber_feta_cheese_olive_oil_onion__afe10915)
      (is_available salad_tongs)
    )
  )
)
