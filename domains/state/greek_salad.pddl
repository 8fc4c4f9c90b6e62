; foon2pddl, encoding state, level 3: 34 of 101 units after relevance pruning
; goal: greek salad (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-state-3d9db31a)
  (:requirements :strips)
  (:constants
    avocado
    banana
    black_olive
    bottle
    bowl
    cucumber
    cutting_board
    feta_cheese
    fork
    greek_salad
    juicer
    knife
    lime
    lime_juice
    olive_oil
    onion
    oregano
    red_wine_vinegar
    salad_tongs
    spoon
    strawberry
    tomato
  )
  (:predicates
    (available ?o)  ; the object is in the kitchen or was made
    (is-chopped ?o)  ; ?o is chopped
    (is-crumbled ?o)  ; ?o is crumbled
    (is-dried ?o)  ; ?o is dried
    (is-empty ?o)  ; ?o is empty
    (is-halved ?o)  ; ?o is halved
    (is-mashed ?o)  ; ?o is mashed
    (is-peeled ?o)  ; ?o is peeled
    (is-pitted ?o)  ; ?o is pitted
    (is-scooped ?o)  ; ?o is scooped
    (is-sliced ?o)  ; ?o is sliced
    (is-squeezed ?o)  ; ?o is squeezed
    (is-whole ?o)  ; ?o is whole
    (contains ?o ?r)  ; ?o contains [?r] or {?r}
    (in ?o ?r)  ; ?o in [?r] or {?r}
    (on ?o ?r)  ; ?o on [?r] or {?r}
  )

  (:action pick-and-place_u47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available onion)
      (is-empty cutting_board)
      (is-whole onion)
    )
    :effect (and
      (contains cutting_board onion)
      (on onion cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action peel_u48
    ; unit 48: peel from 06-tomato_soup.foon:14, 07-guacamole.foon:116, 08-greek_salad.foon:64
    ; peel: cutting board (contains {onion}), onion (on [cutting board], whole), knife -> cutting board (contains {onion}), onion (on [cutting board], peeled), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available onion)
      (contains cutting_board onion)
      (is-whole onion)
      (on onion cutting_board)
    )
    :effect (and
      (is-peeled onion)
      (not (is-whole onion))
    )
  )

  (:action chop_u49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available onion)
      (contains cutting_board onion)
      (is-peeled onion)
      (on onion cutting_board)
    )
    :effect (and
      (is-chopped onion)
      (not (is-peeled onion))
    )
  )

  (:action pick-and-place_u50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available tomato)
      (is-empty cutting_board)
      (is-whole tomato)
    )
    :effect (and
      (contains cutting_board tomato)
      (on tomato cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action chop_u51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available tomato)
      (contains cutting_board tomato)
      (is-whole tomato)
      (on tomato cutting_board)
    )
    :effect (and
      (is-chopped tomato)
      (not (is-whole tomato))
    )
  )

  (:action pick-and-place_u63
    ; unit 63: pick-and-place from 07-guacamole.foon:3
    ; pick-and-place: cutting board (empty), avocado (whole) -> cutting board (contains {avocado}), avocado (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available avocado)
      (available cutting_board)
      (is-empty cutting_board)
      (is-whole avocado)
    )
    :effect (and
      (contains cutting_board avocado)
      (on avocado cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action cut_u64
    ; unit 64: cut from 07-guacamole.foon:14
    ; cut: cutting board (contains {avocado}), avocado (on [cutting board], whole), knife -> cutting board (contains {avocado}), avocado (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (available avocado)
      (available cutting_board)
      (available knife)
      (contains cutting_board avocado)
      (is-whole avocado)
      (on avocado cutting_board)
    )
    :effect (and
      (is-halved avocado)
      (not (is-whole avocado))
    )
  )

  (:action scoop_u65
    ; unit 65: scoop from 07-guacamole.foon:28
    ; scoop: avocado (halved, on [cutting board]), spoon, bowl (empty) -> bowl (contains {avocado}), avocado (in [bowl], scooped), spoon
    :parameters ()
    :precondition (and
      (available avocado)
      (available bowl)
      (available spoon)
      (is-empty bowl)
      (is-halved avocado)
      (on avocado cutting_board)
    )
    :effect (and
      (contains bowl avocado)
      (in avocado bowl)
      (is-scooped avocado)
      (not (is-empty bowl))
      (not (is-halved avocado))
      (not (on avocado cutting_board))
    )
  )

  (:action mash_u66
    ; unit 66: mash from 07-guacamole.foon:42
    ; mash: avocado (in [bowl], scooped), fork -> avocado (in [bowl], mashed), fork
    :parameters ()
    :precondition (and
      (available avocado)
      (available fork)
      (in avocado bowl)
      (is-scooped avocado)
    )
    :effect (and
      (is-mashed avocado)
      (not (is-scooped avocado))
    )
  )

  (:action pick-and-place_u67
    ; unit 67: pick-and-place from 07-guacamole.foon:52, 09-fruit_salad.foon:83
    ; pick-and-place: cutting board (empty), lime (whole) -> cutting board (contains {lime}), lime (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available lime)
      (is-empty cutting_board)
      (is-whole lime)
    )
    :effect (and
      (contains cutting_board lime)
      (on lime cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action cut_u68
    ; unit 68: cut from 07-guacamole.foon:63, 09-fruit_salad.foon:94
    ; cut: cutting board (contains {lime}), lime (on [cutting board], whole), knife -> cutting board (contains {lime}), lime (halved, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available lime)
      (contains cutting_board lime)
      (is-whole lime)
      (on lime cutting_board)
    )
    :effect (and
      (is-halved lime)
      (not (is-whole lime))
    )
  )

  (:action squeeze_u69
    ; unit 69: squeeze from 07-guacamole.foon:77, 09-fruit_salad.foon:108
    ; squeeze: lime (halved, on [cutting board]), juicer (empty) -> lime (squeezed), juicer (contains {lime juice}), lime juice (in [juicer])
    :parameters ()
    :precondition (and
      (available juicer)
      (available lime)
      (is-empty juicer)
      (is-halved lime)
      (on lime cutting_board)
    )
    :effect (and
      (available lime_juice)
      (contains juicer lime_juice)
      (in lime_juice juicer)
      (is-squeezed lime)
      (not (is-empty juicer))
      (not (is-halved lime))
      (not (on lime cutting_board))
    )
  )

  (:action pour_u70
    ; unit 70: pour from 07-guacamole.foon:90
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {avocado}), avocado (in [bowl], mashed) -> bowl (contains {avocado, lime juice}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (available avocado)
      (available bowl)
      (available juicer)
      (available lime_juice)
      (contains bowl avocado)
      (contains juicer lime_juice)
      (in avocado bowl)
      (in lime_juice juicer)
      (is-mashed avocado)
    )
    :effect (and
      (contains bowl lime_juice)
      (in lime_juice bowl)
      (not (in lime_juice juicer))
    )
  )

  (:action pick-and-place_u71
    ; unit 71: pick-and-place from 07-guacamole.foon:144
    ; pick-and-place: bowl (contains {avocado, lime juice}), onion (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion}), onion (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available onion)
      (contains bowl avocado)
      (contains bowl lime_juice)
      (is-chopped onion)
      (on onion cutting_board)
    )
    :effect (and
      (contains bowl onion)
      (in onion bowl)
      (not (on onion cutting_board))
    )
  )

  (:action pick-and-place_u72
    ; unit 72: pick-and-place from 07-guacamole.foon:181
    ; pick-and-place: bowl (contains {avocado, lime juice, onion}), tomato (chopped, on [cutting board]) -> bowl (contains {avocado, lime juice, onion, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available tomato)
      (contains bowl avocado)
      (contains bowl lime_juice)
      (contains bowl onion)
      (is-chopped tomato)
      (on tomato cutting_board)
    )
    :effect (and
      (contains bowl tomato)
      (in tomato bowl)
      (not (on tomato cutting_board))
    )
  )

  (:action pick-and-place_u78
    ; unit 78: pick-and-place from 08-greek_salad.foon:3
    ; pick-and-place: cutting board (empty), cucumber (whole) -> cutting board (contains {cucumber}), cucumber (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cucumber)
      (available cutting_board)
      (is-empty cutting_board)
      (is-whole cucumber)
    )
    :effect (and
      (contains cutting_board cucumber)
      (on cucumber cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action slice_u79
    ; unit 79: slice from 08-greek_salad.foon:14
    ; slice: cutting board (contains {cucumber}), cucumber (on [cutting board], whole), knife -> cutting board (contains {cucumber}), cucumber (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (available cucumber)
      (available cutting_board)
      (available knife)
      (contains cutting_board cucumber)
      (is-whole cucumber)
      (on cucumber cutting_board)
    )
    :effect (and
      (is-sliced cucumber)
      (not (is-whole cucumber))
    )
  )

  (:action slice_u80
    ; unit 80: slice from 08-greek_salad.foon:78
    ; slice: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available onion)
      (contains cutting_board onion)
      (is-peeled onion)
      (on onion cutting_board)
    )
    :effect (and
      (is-sliced onion)
      (not (is-peeled onion))
    )
  )

  (:action pick-and-place_u81
    ; unit 81: pick-and-place from 08-greek_salad.foon:92
    ; pick-and-place: bowl (empty), cucumber (on [cutting board], sliced) -> bowl (contains {cucumber}), cucumber (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (available bowl)
      (available cucumber)
      (is-empty bowl)
      (is-sliced cucumber)
      (on cucumber cutting_board)
    )
    :effect (and
      (contains bowl cucumber)
      (in cucumber bowl)
      (not (is-empty bowl))
      (not (on cucumber cutting_board))
    )
  )

  (:action pick-and-place_u82
    ; unit 82: pick-and-place from 08-greek_salad.foon:104
    ; pick-and-place: bowl (contains {cucumber}), tomato (chopped, on [cutting board]) -> bowl (contains {cucumber, tomato}), tomato (chopped, in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available tomato)
      (contains bowl cucumber)
      (is-chopped tomato)
      (on tomato cutting_board)
    )
    :effect (and
      (contains bowl tomato)
      (in tomato bowl)
      (not (on tomato cutting_board))
    )
  )

  (:action pick-and-place_u83
    ; unit 83: pick-and-place from 08-greek_salad.foon:116
    ; pick-and-place: bowl (contains {cucumber, tomato}), onion (on [cutting board], sliced) -> bowl (contains {cucumber, onion, tomato}), onion (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (available bowl)
      (available onion)
      (contains bowl cucumber)
      (contains bowl tomato)
      (is-sliced onion)
      (on onion cutting_board)
    )
    :effect (and
      (contains bowl onion)
      (in onion bowl)
      (not (on onion cutting_board))
    )
  )

  (:action pick-and-place_u84
    ; unit 84: pick-and-place from 08-greek_salad.foon:128
    ; pick-and-place: bowl (contains {cucumber, onion, tomato}), black olive (pitted) -> bowl (contains {black olive, cucumber, onion, tomato}), black olive (in [bowl], pitted)
    :parameters ()
    :precondition (and
      (available black_olive)
      (available bowl)
      (contains bowl cucumber)
      (contains bowl onion)
      (contains bowl tomato)
      (is-pitted black_olive)
    )
    :effect (and
      (contains bowl black_olive)
      (in black_olive bowl)
    )
  )

  (:action sprinkle_u85
    ; unit 85: sprinkle from 08-greek_salad.foon:139
    ; sprinkle: bowl (contains {black olive, cucumber, onion, tomato}), feta cheese (crumbled) -> bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), feta cheese (crumbled, in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available feta_cheese)
      (contains bowl black_olive)
      (contains bowl cucumber)
      (contains bowl onion)
      (contains bowl tomato)
      (is-crumbled feta_cheese)
    )
    :effect (and
      (contains bowl feta_cheese)
      (in feta_cheese bowl)
    )
  )

  (:action pour_u86
    ; unit 86: pour* from 08-greek_salad.foon:150
    ; pour: bowl (contains {black olive, cucumber, feta cheese, onion, tomato}), olive oil (in [bottle]), red wine vinegar (in [bottle]) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), olive...
    :parameters ()
    :precondition (and
      (available bowl)
      (available olive_oil)
      (available red_wine_vinegar)
      (contains bowl black_olive)
      (contains bowl cucumber)
      (contains bowl feta_cheese)
      (contains bowl onion)
      (contains bowl tomato)
      (in olive_oil bottle)
      (in red_wine_vinegar bottle)
    )
    :effect (and
      (contains bowl olive_oil)
      (contains bowl red_wine_vinegar)
      (in olive_oil bowl)
      (in red_wine_vinegar bowl)
      (not (in olive_oil bottle))
      (not (in red_wine_vinegar bottle))
    )
  )

  (:action sprinkle_u87
    ; unit 87: sprinkle from 08-greek_salad.foon:164
    ; sprinkle: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, red wine vinegar, tomato}), oregano (dried) -> bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), ore...
    :parameters ()
    :precondition (and
      (available bowl)
      (available oregano)
      (contains bowl black_olive)
      (contains bowl cucumber)
      (contains bowl feta_cheese)
      (contains bowl olive_oil)
      (contains bowl onion)
      (contains bowl red_wine_vinegar)
      (contains bowl tomato)
      (is-dried oregano)
    )
    :effect (and
      (contains bowl oregano)
      (in oregano bowl)
      (not (is-dried oregano))
    )
  )

  (:action toss_u88
    ; unit 88: toss from 08-greek_salad.foon:174
    ; toss: bowl (contains {black olive, cucumber, feta cheese, olive oil, onion, oregano, red wine vinegar, tomato}), cucumber (in [bowl], sliced), tomato (chopped, in [bowl]), onion (in [bowl], sliced), black olive (in [bowl], pitted), feta ...
    :parameters ()
    :precondition (and
      (available black_olive)
      (available bowl)
      (available cucumber)
      (available feta_cheese)
      (available olive_oil)
      (available onion)
      (available oregano)
      (available red_wine_vinegar)
      (available salad_tongs)
      (available tomato)
      (contains bowl black_olive)
      (contains bowl cucumber)
      (contains bowl feta_cheese)
      (contains bowl olive_oil)
      (contains bowl onion)
      (contains bowl oregano)
      (contains bowl red_wine_vinegar)
      (contains bowl tomato)
      (in black_olive bowl)
      (in cucumber bowl)
      (in feta_cheese bowl)
      (in olive_oil bowl)
      (in onion bowl)
      (in oregano bowl)
      (in red_wine_vinegar bowl)
      (in tomato bowl)
      (is-chopped tomato)
      (is-crumbled feta_cheese)
      (is-pitted black_olive)
      (is-sliced cucumber)
      (is-sliced onion)
    )
    :effect (and
      (available greek_salad)
      (contains bowl greek_salad)
      (contains greek_salad black_olive)
      (contains greek_salad cucumber)
      (contains greek_salad feta_cheese)
      (contains greek_salad olive_oil)
      (contains greek_salad onion)
      (contains greek_salad oregano)
      (contains greek_salad red_wine_vinegar)
      (contains greek_salad tomato)
      (in greek_salad bowl)
      (not (contains bowl black_olive))
      (not (contains bowl cucumber))
      (not (contains bowl feta_cheese))
      (not (contains bowl olive_oil))
      (not (contains bowl onion))
      (not (contains bowl oregano))
      (not (contains bowl red_wine_vinegar))
      (not (contains bowl tomato))
    )
  )

  (:action pick-and-place_u89
    ; unit 89: pick-and-place from 09-fruit_salad.foon:3
    ; pick-and-place: cutting board (empty), strawberry (whole) -> cutting board (contains {strawberry}), strawberry (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available strawberry)
      (is-empty cutting_board)
      (is-whole strawberry)
    )
    :effect (and
      (contains cutting_board strawberry)
      (on strawberry cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action slice_u90
    ; unit 90: slice from 09-fruit_salad.foon:14
    ; slice: cutting board (contains {strawberry}), strawberry (on [cutting board], whole), knife -> cutting board (contains {strawberry}), strawberry (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available strawberry)
      (contains cutting_board strawberry)
      (is-whole strawberry)
      (on strawberry cutting_board)
    )
    :effect (and
      (is-sliced strawberry)
      (not (is-whole strawberry))
    )
  )

  (:action peel_u91
    ; unit 91: peel from 09-fruit_salad.foon:28
    ; peel: banana (whole) -> banana (peeled)
    :parameters ()
    :precondition (and
      (available banana)
      (is-whole banana)
    )
    :effect (and
      (is-peeled banana)
      (not (is-whole banana))
    )
  )

  (:action pick-and-place_u92
    ; unit 92: pick-and-place from 09-fruit_salad.foon:34
    ; pick-and-place: cutting board (empty), banana (peeled) -> cutting board (contains {banana}), banana (on [cutting board], peeled)
    :parameters ()
    :precondition (and
      (available banana)
      (available cutting_board)
      (is-empty cutting_board)
      (is-peeled banana)
    )
    :effect (and
      (contains cutting_board banana)
      (on banana cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action slice_u93
    ; unit 93: slice from 09-fruit_salad.foon:45
    ; slice: cutting board (contains {banana}), banana (on [cutting board], peeled), knife -> cutting board (contains {banana}), banana (on [cutting board], sliced), knife
    :parameters ()
    :precondition (and
      (available banana)
      (available cutting_board)
      (available knife)
      (contains cutting_board banana)
      (is-peeled banana)
      (on banana cutting_board)
    )
    :effect (and
      (is-sliced banana)
      (not (is-peeled banana))
    )
  )

  (:action pick-and-place_u94
    ; unit 94: pick-and-place from 09-fruit_salad.foon:59
    ; pick-and-place: bowl (empty), strawberry (on [cutting board], sliced) -> bowl (contains {strawberry}), strawberry (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (available bowl)
      (available strawberry)
      (is-empty bowl)
      (is-sliced strawberry)
      (on strawberry cutting_board)
    )
    :effect (and
      (contains bowl strawberry)
      (in strawberry bowl)
      (not (is-empty bowl))
      (not (on strawberry cutting_board))
    )
  )

  (:action pick-and-place_u95
    ; unit 95: pick-and-place from 09-fruit_salad.foon:71
    ; pick-and-place: bowl (contains {strawberry}), banana (on [cutting board], sliced) -> bowl (contains {banana, strawberry}), banana (in [bowl], sliced)
    :parameters ()
    :precondition (and
      (available banana)
      (available bowl)
      (contains bowl strawberry)
      (is-sliced banana)
      (on banana cutting_board)
    )
    :effect (and
      (contains bowl banana)
      (in banana bowl)
      (not (on banana cutting_board))
    )
  )

  (:action pour_u96
    ; unit 96: pour from 09-fruit_salad.foon:121
    ; pour: juicer (contains {lime juice}), lime juice (in [juicer]), bowl (contains {banana, strawberry}) -> bowl (contains {banana, lime juice, strawberry}), lime juice (in [bowl])
    :parameters ()
    :precondition (and
      (available bowl)
      (available juicer)
      (available lime_juice)
      (contains bowl banana)
      (contains bowl strawberry)
      (contains juicer lime_juice)
      (in lime_juice juicer)
    )
    :effect (and
      (contains bowl lime_juice)
      (in lime_juice bowl)
      (not (in lime_juice juicer))
    )
  )
)
