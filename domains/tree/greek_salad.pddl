; foon2pddl, encoding tree, level 3: 26 of 101 units after relevance pruning
; goal: greek salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-tree-9e756b3e)
  (:requirements :strips)
  (:predicates
    (avocado_halved_on_cutting_board)  ; avocado (halved, on [cutting board])
    (avocado_in_bowl_mashed)  ; avocado (in [bowl], mashed)
    (avocado_in_bowl_scooped)  ; avocado (in [bowl], scooped)
    (avocado_on_cutting_board_whole)  ; avocado (on [cutting board], whole)
    (avocado_whole)  ; avocado (whole)
    (black_olive_in_bowl_pitted)  ; black olive (in [bowl], pitted)
    (black_olive_pitted)  ; black olive (pitted)
    (bowl_contains_avocado)  ; bowl (contains {avocado})
    (bowl_contains_avocado_lime_juice)  ; bowl (contains {avocado, lime juice})
    (bowl_contains_avocado_lime_juice_onion)  ; bowl (contains {avocado, lime juice, onion})
    (bowl_contains_avocado_lime_juice_onion_tomato)  ; bowl (contains {avocado, lime juice, onion, tomato})
    (bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6)  ; bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato})
    (bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4)  ; bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato})
    (bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato)  ; bowl (contains {black olive, cucumber, feta cheese, onion, tomato})
    (bowl_contains_black_olive_cucumber_onion_tomato)  ; bowl (contains {black olive, cucumber, onion, tomato})
    (bowl_contains_cucumber)  ; bowl (contains {cucumber})
    (bowl_contains_cucumber_onion_tomato)  ; bowl (contains {cucumber, onion, tomato})
    (bowl_contains_cucumber_tomato)  ; bowl (contains {cucumber, tomato})
    (bowl_contains_greek_salad)  ; bowl (contains {greek salad})
    (bowl_empty)  ; bowl (empty)
    (cucumber_in_bowl_sliced)  ; cucumber (in [bowl], sliced)
    (cucumber_on_cutting_board_sliced)  ; cucumber (on [cutting board], sliced)
    (cucumber_on_cutting_board_whole)  ; cucumber (on [cutting board], whole)
    (cucumber_whole)  ; cucumber (whole)
    (cutting_board_contains_avocado)  ; cutting board (contains {avocado})
    (cutting_board_contains_cucumber)  ; cutting board (contains {cucumber})
    (cutting_board_contains_lime)  ; cutting board (contains {lime})
    (cutting_board_contains_onion)  ; cutting board (contains {onion})
    (cutting_board_contains_tomato)  ; cutting board (contains {tomato})
    (cutting_board_empty)  ; cutting board (empty)
    (feta_cheese_crumbled)  ; feta cheese (crumbled)
    (feta_cheese_crumbled_in_bowl)  ; feta cheese (crumbled, in [bowl])
    (fork)  ; fork
    (greek_salad_contains_black_olive_cucumber_feta_cheese_olive_oil_onion__afe10915)  ; greek salad (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}, in [bowl])
    (juicer_contains_lime_juice)  ; juicer (contains {lime juice})
    (juicer_empty)  ; juicer (empty)
    (knife)  ; knife
    (lime_halved_on_cutting_board)  ; lime (halved, on [cutting board])
    (lime_on_cutting_board_whole)  ; lime (on [cutting board], whole)
    (lime_squeezed)  ; lime (squeezed)
    (lime_whole)  ; lime (whole)
    (lime_juice_in_bowl)  ; lime juice (in [bowl])
    (lime_juice_in_juicer)  ; lime juice (in [juicer])
    (olive_oil_in_bottle)  ; olive oil (in [bottle])
    (olive_oil_in_bowl)  ; olive oil (in [bowl])
    (onion_chopped_in_bowl)  ; onion (chopped, in [bowl])
    (onion_chopped_on_cutting_board)  ; onion (chopped, on [cutting board])
    (onion_in_bowl_sliced)  ; onion (in [bowl], sliced)
    (onion_on_cutting_board_peeled)  ; onion (on [cutting board], peeled)
    (onion_on_cutting_board_sliced)  ; onion (on [cutting board], sliced)
    (onion_on_cutting_board_whole)  ; onion (on [cutting board], whole)
    (onion_whole)  ; onion (whole)
    (oregano_dried)  ; oregano (dried)
    (oregano_in_bowl)  ; oregano (in [bowl])
    (red_wine_vinegar_in_bottle)  ; red wine vinegar (in [bottle])
    (red_wine_vinegar_in_bowl)  ; red wine vinegar (in [bowl])
    (salad_tongs)  ; salad tongs
    (spoon)  ; spoon
    (tomato_chopped_in_bowl)  ; tomato (chopped, in [bowl])
    (tomato_chopped_on_cutting_board)  ; tomato (chopped, on [cutting board])
    (tomato_on_cutting_board_whole)  ; tomato (on [cutting board], whole)
    (tomato_whole)  ; tomato (whole)
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

  (:action pick-and-place_u78
    ; unit 78: pick-and-place from 08-greek_salad.foon:3
    ; pick-and-place: cutting board (empty), cucumber (whole) -> cutting board (contains {cucumber}), cucumber (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (cucumber_whole)
      (cutting_board_empty)
    )
    :effect (and
      (cucumber_on_cutting_board_whole)
      (cutting_board_contains_cucumber)
    )
  )

  (:action slice_u79
    ; unit 79: slice from 08-greek_salad.foon:14
    ; slice: cutting board (contains {cucumber}), cucumber (on [cutting board], whole), knife -> cutting board (contains {cucumber}), cucumber (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (cucumber_on_cutting_board_whole)
      (cutting_board_contains_cucumber)
      (knife)
    )
    :effect (and
      (cucumber_on_cutting_board_sliced)
      (cutting_board_contains_cucumber)
      (knife)
    )
  )

  (:action slice_u80
    ; unit 80: slice from 08-greek_salad.foon:78
    ; slice: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (cutting_board_contains_onion)
      (knife)
      (onion_on_cutting_board_peeled)
    )
    :effect (and
      (cutting_board_contains_onion)
      (knife)
      (onion_on_cutting_board_sliced)
    )
  )

  (:action pick-and-place_u81
    ; unit 81: pick-and-place from 08-greek_salad.foon:92
    ; pick-and-place: bowl (empty), cucumber (on [cutting board], sliced) -> bowl (contains {cucumber}), cucumber (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (bowl_empty)
      (cucumber_on_cutting_board_sliced)
    )
    :effect (and
      (bowl_contains_cucumber)
      (cucumber_in_bowl_sliced)
    )
  )

  (:action pick-and-place_u82
    ; unit 82: pick-and-place from 08-greek_salad.foon:104
    ; pick-and-place: bowl (contains {cucumber}), tomato (chopped, on [cutting board]) -> bowl (contains {cucumber, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (bowl_contains_cucumber)
      (tomato_chopped_on_cutting_board)
    )
    :effect (and
      (bowl_contains_cucumber_tomato)
      (tomato_chopped_in_bowl)
    )
  )

  (:action pick-and-place_u83
    ; unit 83: pick-and-place from 08-greek_salad.foon:116
    ; pick-and-place: bowl (contains {cucumber, tomato}), onion (on [cutting board], sliced) -> bowl (contains {cucumber, onion, tomato}), onion (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (bowl_contains_cucumber_tomato)
      (onion_on_cutting_board_sliced)
    )
    :effect (and
      (bowl_contains_cucumber_onion_tomato)
      (onion_in_bowl_sliced)
    )
  )

  (:action pick-and-place_u84
    ; unit 84: pick-and-place from 08-greek_salad.foon:128
    ; pick-and-place: bowl (contains {cucumber, onion, tomato}), black olive (pitted) -> bowl (contains {black olive, cucumber, onion, tomato}), black olive (in [bowl], pitted)
    :parameters ()
    :precondition (and
      (black_olive_pitted)
      (bowl_contains_cucumber_onion_tomato)
    )
    :effect (and
      (black_olive_in_bowl_pitted)
      (bowl_contains_black_olive_cucumber_onion_tomato)
    )
  )

  (:action sprinkle_u85
    ; unit 85: sprinkle from 08-greek_salad.foon:139
    ; sprinkle: bowl (contains {black olive, cucumber, onion, tomato}), feta cheese (crumbled) -> bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), feta cheese (crumbled, in [bowl])
    :parameters ()
    :precondition (and
      (bowl_contains_black_olive_cucumber_onion_tomato)
      (feta_cheese_crumbled)
    )
    :effect (and
      (bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato)
      (feta_cheese_crumbled_in_bowl)
    )
  )

  (:action pour_u86
    ; unit 86: pour* from 08-greek_salad.foon:150
    ; pour: bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), olive oil (in [bottle]), red wine vinegar (in [bottle]) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), olive...
    :parameters ()
    :precondition (and
      (bowl_contains_black_olive_cucumber_feta_cheese_onion_tomato)
      (olive_oil_in_bottle)
      (red_wine_vinegar_in_bottle)
    )
    :effect (and
      (bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4)
      (olive_oil_in_bowl)
      (red_wine_vinegar_in_bowl)
    )
  )

  (:action sprinkle_u87
    ; unit 87: sprinkle from 08-greek_salad.foon:164
    ; sprinkle: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), oregano (dried) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), ore...
    :parameters ()
    :precondition (and
      (bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_red_win__cb6a28c4)
      (oregano_dried)
    )
    :effect (and
      (bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6)
      (oregano_in_bowl)
    )
  )

  (:action toss_u88
    ; unit 88: toss from 08-greek_salad.foon:174
    ; toss: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), cucumber (in [bowl], sliced), tomato (chopped, in [bowl]), onion (in [bowl], sliced), black olive (in [bowl], pitted), feta ...
    :parameters ()
    :precondition (and
      (black_olive_in_bowl_pitted)
      (bowl_contains_black_olive_cucumber_feta_cheese_olive_oil_onion_oregano__c6f423c6)
      (cucumber_in_bowl_sliced)
      (feta_cheese_crumbled_in_bowl)
      (olive_oil_in_bowl)
      (onion_in_bowl_sliced)
      (oregano_in_bowl)
      (red_wine_vinegar_in_bowl)
      (salad_tongs)
      (tomato_chopped_in_bowl)
    )
    :effect (and
      (bowl_contains_greek_salad)
      (greek_salad_contains_black_olive_cucumber_feta_cheese_olive_oil_onion__afe10915)
      (salad_tongs)
    )
  )
)
